#!/usr/bin/env bash
# layout.json, as `epure generate` writes it beside key.json, against the PDF it describes
# (tests/tools/layout_check.py): every page of every sheet rendered and read where layout.json
# says — the four corner marks solid, the page code's finder patterns, every comb cell's and tick
# box's printed sides, paper inside; every question of key.json with its field. French on A4
# and English on Letter, every difficulty's fields over the sets. And deterministic: the same
# bytes with one job or two, with or without the SVG pages.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
ok() { echo "ok   $*"; }
bad() { echo "FAIL $*"; fail=1; }
checker=$EPURE_SOURCE_DIR/tests/tools/layout_check.py
export SOURCE_DATE_EPOCH=1700000000

for run in "fr a4 easy 7" "en letter hard 8" "fr a4 standard 9"; do
  set -- $run
  out=$tmp/$1-$2-$3
  "$EPURE" generate --quiet --format pdf --sheets 4 --seed "$4" --lang "$1" --paper "$2" --difficulty "$3" --jobs 2 --out "$out" ||
    { bad "generate $run"; continue; }
  python3 "$checker" "$out" >"$out.log" 2>&1 && ok "$run: $(cat "$out.log")" || bad "$run: $(head -20 "$out.log")"
done

out=$tmp/fr-a4-easy
"$EPURE" generate --quiet --format pdf --sheets 4 --seed 7 --lang fr --paper a4 --difficulty easy --jobs 1 --out "$tmp/one" &&
  cmp -s "$out/layout.json" "$tmp/one/layout.json" && ok "the same layout.json with one job or two" ||
  bad "layout.json differs with one job and two"
"$EPURE" generate --quiet --format svg,pdf --sheets 4 --seed 7 --lang fr --paper a4 --difficulty easy --jobs 2 --out "$tmp/both" &&
  cmp -s "$out/layout.json" "$tmp/both/layout.json" && ok "the same layout.json with the SVG pages" ||
  bad "layout.json differs with the SVG pages"
# layout.json is read back by scan's own reader: a scan of nothing finds the layout and the key
# agree (exit status 2 would say the layout or the key was refused)
printf 'not an image' >"$tmp/empty.png"
"$EPURE" scan "$tmp/empty.png" --key "$out/key.json" --out "$tmp/scan" -q 2>"$tmp/scan.err"
[ $? -eq 1 ] && ok "scan reads generate's layout.json beside key.json" || bad "scan refused generate's layout.json: $(cat "$tmp/scan.err")"
exit $fail
