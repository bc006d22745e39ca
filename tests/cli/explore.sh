#!/usr/bin/env bash
# `epure explore`: one self-contained explore.html (no URL to fetch), in the language asked,
# beside index.html after `epure generate`, linked from it; a binary built without the page
# (no em++, or -DEPURE_EXPLORE=OFF as the ASan build) says so. The page itself: tests/browser.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

"$EPURE" explore --out "$tmp/x" --lang fr >"$tmp/out" 2>"$tmp/err"
status=$?
if grep -q 'built without the explorer page' "$tmp/err"; then
  [ $status -eq 1 ] || fail "without the page: status $status, expected 1"
  [ -e "$tmp/x/explore.html" ] && fail "without the page: explore.html written"
  "$EPURE" generate --format svg --sheets 1 --quiet --out "$tmp/set" || fail "generate failed"
  [ -e "$tmp/set/explore.html" ] && fail "without the page: generate wrote explore.html"
  grep -q 'explore.html' "$tmp/set/index.html" && fail "without the page: index.html links explore.html"
  "$EPURE" generate --format svg,pdf --sheets 1 --quiet --out "$tmp/pdfset" || fail "generate (svg,pdf) failed"
  pdfinfo -url "$tmp/pdfset/keys.pdf" | grep -q 'explore.html' && fail "without the page: keys.pdf links explore.html"
  [ $failed -eq 0 ] && echo "explore (binary without the page): ok"
  exit $failed
fi
[ $status -eq 0 ] || fail "epure explore: status $status: $(cat "$tmp/err")"
page=$tmp/x/explore.html
[ -s "$page" ] || fail "no explore.html"
[ "$(ls "$tmp/x")" = explore.html ] || fail "more than explore.html written: $(ls "$tmp/x")"
# self-contained: no external script, style, image or URL of any scheme but data:
grep -Eq '(src|href)="(https?:|//|[a-z0-9_./-]+\.(js|wasm|css))' "$page" && fail "explore.html refers to another file"
grep -q '<script id="epure-config" type="application/json">{"lang":"fr","set":{}}</script>' "$page" ||
  fail "the page does not open in French"
grep -q 'data:application/octet-stream;base64,' "$page" || fail "no inlined WebAssembly"
# its language and title in the markup itself, before any script runs
grep -q '^<html lang="fr">$' "$page" || fail "explore.html is not lang=\"fr\": $(grep -m1 '<html' "$page")"
grep -q '^<title>epure — corrigés à manipuler</title>$' "$page" || fail "explore.html's title: $(grep -m1 '<title' "$page")"
"$EPURE" explore --out "$tmp/y" --lang de 2>"$tmp/err2" && fail "--lang de accepted"
[ -s "$tmp/err2" ] || fail "--lang de: no message"
# generate writes it beside index.html, with the set's instances, and links each exercise
"$EPURE" generate --format svg --sheets 2 --quiet --out "$tmp/set" || fail "generate failed"
[ -s "$tmp/set/explore.html" ] || fail "generate wrote no explore.html"
id=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["sheets"][1]["id"])' "$tmp/set/key.json")
grep -q "href=\"explore.html#$id.1\"" "$tmp/set/index.html" || fail "index.html has no link to explore.html#$id.1"
grep -q "\"$id\":\[\"{\\\\\"kind\\\\\"" "$tmp/set/explore.html" || fail "explore.html does not hold sheet $id (its instances as their text)"
# and what the sheets call their exercises, in both languages, so that a linked one is titled
# as on its paper
grep -q '"labels":{"en":\["Preamble","Exercise 1",' "$tmp/set/explore.html" || fail "explore.html has no exercise labels"
grep -q '"fr":\["Préambule","Exercice 1",' "$tmp/set/explore.html" || fail "explore.html has no French exercise labels"
# the keys' PDFs link each exercise's heading to explore.html#<sheet id>.<n> (tests/cli/pdf.sh
# checks every link, --duplex and --split, and qpdf --check); here: a PDF reader (poppler) sees it
"$EPURE" generate --sheets 2 --seed 5 --quiet --out "$tmp/pdf" || fail "generate (svg,pdf) failed"
pdfinfo -url "$tmp/pdf/keys.pdf" | grep -q "explore.html#$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["sheets"][0]["id"])' "$tmp/pdf/key.json").1\$" ||
  fail "pdfinfo -url: keys.pdf has no link to its first exercise"
[ $failed -eq 0 ] && echo "explore: ok"
exit $failed
