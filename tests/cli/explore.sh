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
  "$EPURE" generate --format pdf --sheets 1 --quiet --out "$tmp/pdfset" || fail "generate (pdf) failed"
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
"$EPURE" explore --out "$tmp/y" --lang de 2>"$tmp/err2" && fail "--lang de accepted"
[ -s "$tmp/err2" ] || fail "--lang de: no message"
# generate writes it beside index.html, with the set's instances, and links each exercise
"$EPURE" generate --format svg --sheets 2 --quiet --out "$tmp/set" || fail "generate failed"
[ -s "$tmp/set/explore.html" ] || fail "generate wrote no explore.html"
id=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["sheets"][1]["id"])' "$tmp/set/key.json")
grep -q "href=\"explore.html#$id.1\"" "$tmp/set/index.html" || fail "index.html has no link to explore.html#$id.1"
grep -q "\"$id\":\[{\"kind\"" "$tmp/set/explore.html" || fail "explore.html does not hold sheet $id"
# the keys' PDFs link each exercise's heading to explore.html#<sheet id>.<n> (relative: keys.pdf
# sits beside explore.html; a --split key one directory below), the sheets' PDFs link nowhere, and
# the bytes stay the same from one run to the next
"$EPURE" generate --sheets 2 --seed 5 --jobs 2 --quiet --out "$tmp/pdf" || fail "generate (svg,pdf) failed"
"$EPURE" generate --sheets 2 --seed 5 --jobs 1 --quiet --out "$tmp/pdf2" || fail "generate (svg,pdf) failed"
"$EPURE" generate --sheets 2 --seed 5 --split --quiet --out "$tmp/split" || fail "generate --split failed"
cmp -s "$tmp/pdf/keys.pdf" "$tmp/pdf2/keys.pdf" || fail "keys.pdf with links differs from one run to the next"
pdfinfo -url "$tmp/pdf/keys.pdf" >"$tmp/urls" || fail "pdfinfo -url keys.pdf"
pdfinfo -url "$tmp/pdf/sheets.pdf" | grep -q 'explore.html' && fail "sheets.pdf links explore.html"
python3 - "$tmp/pdf/key.json" "$tmp/urls" "$tmp/split" <<'PY' || fail "the keys' links to explore.html"
import json, subprocess, sys
key = json.load(open(sys.argv[1]))
want = [f"explore.html#{s['id']}.{e['n']}" for s in key["sheets"] for e in s["exercises"]]
rows = [l.split() for l in open(sys.argv[2]) if "explore.html" in l]
got = [r[-1] for r in rows]
pages = [int(r[0]) for r in rows]
ok = True
if got != want:
    print(f"keys.pdf links {got}, expected {want}"); ok = False
if not pages or pages[0] != 1 or pages != sorted(pages):
    print(f"keys.pdf links on pages {pages}: the first exercise on page 1, in order"); ok = False
for s in key["sheets"]:
    out = subprocess.run(["pdfinfo", "-url", f"{sys.argv[3]}/keys/{s['id']}.pdf"], capture_output=True, text=True).stdout
    split = [l.split()[-1] for l in out.splitlines() if "explore.html" in l]
    if split != [f"../explore.html#{s['id']}.{e['n']}" for e in s["exercises"]]:
        print(f"keys/{s['id']}.pdf links {split}"); ok = False
sys.exit(0 if ok else 1)
PY
[ $failed -eq 0 ] && echo "explore: ok"
exit $failed
