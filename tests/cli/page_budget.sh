#!/usr/bin/env bash
# Issue 18's page budget on the default course (30 sheets, seed 1, A4), counted from the SVG
# pages of each sheet and key: a key takes at most 6 pages on average in every language and
# difficulty; a sheet at most 4 pages where that is reached (en easy and hard); elsewhere no more
# sheets on 5 pages, and no more key pages, than measured on 2026-12-03 (bench/README.md,
# "Pages"), so that a change of the layout or of the kinds' texts that costs pages fails here.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; status=1; }
status=0
# language, difficulty, most sheets over 4 pages, most pages a sheet, most key pages in all
for row in "en easy 0 4 162" "en standard 3 5 164" "en hard 0 4 167" \
           "fr easy 1 5 169" "fr standard 4 5 169" "fr hard 2 5 172"; do
  set -- $row
  out=$tmp/$1-$2
  "$EPURE" generate --quiet --format svg --sheets 30 --seed 1 --lang "$1" --difficulty "$2" --paper a4 \
    --jobs 2 --out "$out" || { echo "FAIL: generate $1 $2"; exit 1; }
  for kind in sheets keys; do
    counts=$(for f in "$out/$kind"/*.svg; do grep -o 'class="page"' "$f" | wc -l; done)
    n=$(echo "$counts" | wc -l)
    [ "$n" -eq 30 ] || fail "$1 $2 $kind: $n files, not 30"
    total=$(echo "$counts" | awk '{ s += $1 } END { print s }')
    max=$(echo "$counts" | sort -n | tail -1)
    over=$(echo "$counts" | awk '$1 > 4' | wc -l)
    echo "$1 $2 $kind: $total pages, max $max, $over over 4"
    if [ "$kind" = sheets ]; then
      [ "$over" -le "$3" ] || fail "$1 $2: $over sheets over 4 pages (at most $3)"
      [ "$max" -le "$4" ] || fail "$1 $2: a sheet on $max pages (at most $4)"
    else
      [ "$total" -le 180 ] || fail "$1 $2: keys $total pages, more than 6 a key on average"
      [ "$total" -le "$5" ] || fail "$1 $2: keys $total pages (at most $5)"
    fi
  done
done
[ $status -eq 0 ] && echo "page budget: ok"
exit $status
