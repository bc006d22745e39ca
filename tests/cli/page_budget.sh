#!/usr/bin/env bash
# Issue 18's page budget on the default course (30 sheets, A4), counted from the SVG pages of
# each sheet and key, on seeds 1, 2 and 3, in both languages and every difficulty:
# - every student's sheet on at most 4 pages (two sheets of paper printed duplex); the layout
#   sets a sheet's tallest figures smaller where that is what it takes (layout.h);
# - a key on at most 6 pages on average; on seed 1, no more key pages than measured on
#   2026-12-03 (bench/README.md, "Pages"), so that a change of the layout or of the kinds' texts
#   that costs pages fails here.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; status=1; }
status=0
for seed in 1 2 3; do
  # language, difficulty, most key pages in all (seed 1)
  for row in "en easy 162" "en standard 164" "en hard 167" "fr easy 169" "fr standard 169" "fr hard 172"; do
    set -- $row
    out=$tmp/$seed-$1-$2
    "$EPURE" generate --quiet --format svg --sheets 30 --seed "$seed" --lang "$1" --difficulty "$2" --paper a4 \
      --jobs 2 --out "$out" || { echo "FAIL: generate seed $seed $1 $2"; exit 1; }
    for kind in sheets keys; do
      counts=$(for f in "$out/$kind"/*.svg; do grep -o 'class="page"' "$f" | wc -l; done)
      n=$(echo "$counts" | wc -l)
      [ "$n" -eq 30 ] || fail "seed $seed $1 $2 $kind: $n files, not 30"
      total=$(echo "$counts" | awk '{ s += $1 } END { print s }')
      max=$(echo "$counts" | sort -n | tail -1)
      echo "seed $seed $1 $2 $kind: $total pages, max $max"
      if [ "$kind" = sheets ]; then
        [ "$max" -le 4 ] || fail "seed $seed $1 $2: a sheet on $max pages (at most 4)"
      else
        [ "$total" -le 180 ] || fail "seed $seed $1 $2: keys $total pages, more than 6 a key on average"
        [ "$seed" -ne 1 ] || [ "$total" -le "$3" ] || fail "seed 1 $1 $2: keys $total pages (at most $3)"
      fi
    done
  done
done
[ $status -eq 0 ] && echo "page budget: ok"
exit $status
