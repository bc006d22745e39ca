#!/usr/bin/env bash
# The page budget on the default course (30 sheets), counted from the SVG pages of each sheet
# and key, in both languages and every difficulty: A4 on seeds 1, 2 and 3, Letter on seed 1
# (tests/render/sheet_pages_test.cpp checks Letter on other seeds, from the layout's boxes):
# - every student's sheet on at most 4 pages (two sheets of paper printed duplex), each exercise
#   on one page; the layout sets some sections' figures smaller where that is what it takes
#   (layout.h);
# - a key on at most 6 pages on average; on seed 1, no more key pages than measured on
#   2026-12-05 (bench/README.md, "Pages"; then 0–3 more a set for the sentence that says where
#   the circle and the square depart from the course; then 1 more in three sets for the legend
#   line under the square's, the rectangle's and the cube's key figures, issue 34; then 1 more
#   in three A4 sets for the worked steps' values at 4 significant digits, issue 31; then
#   measured again for draw version 2, whose work-fair draw gives seed 1's sheets other cases:
#   A4 −4 to +1 a set, Letter +2 to +5, the keys evener in length), so that a change of the
#   layout or of the kinds' texts that costs pages fails here.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; status=1; }
status=0
for run in "1 a4" "2 a4" "3 a4" "1 letter"; do
  set -- $run
  seed=$1 paper=$2
  # language, difficulty, most key pages in all (seed 1): A4, Letter
  for row in "en easy 161 178" "en standard 168 176" "en hard 169 179" \
             "fr easy 171 180" "fr standard 171 179" "fr hard 175 180"; do
    set -- $row
    most=$3; [ "$paper" = letter ] && most=$4
    out=$tmp/$seed-$paper-$1-$2
    "$EPURE" generate --quiet --format svg --sheets 30 --seed "$seed" --lang "$1" --difficulty "$2" --paper "$paper" \
      --jobs 2 --out "$out" || { echo "FAIL: generate seed $seed $paper $1 $2"; exit 1; }
    for kind in sheets keys; do
      counts=$(for f in "$out/$kind"/*.svg; do grep -o 'class="page"' "$f" | wc -l; done)
      n=$(echo "$counts" | wc -l)
      [ "$n" -eq 30 ] || fail "seed $seed $paper $1 $2 $kind: $n files, not 30"
      total=$(echo "$counts" | awk '{ s += $1 } END { print s }')
      max=$(echo "$counts" | sort -n | tail -1)
      echo "seed $seed $paper $1 $2 $kind: $total pages, max $max"
      if [ "$kind" = sheets ]; then
        [ "$max" -le 4 ] || fail "seed $seed $paper $1 $2: a sheet on $max pages (at most 4)"
      else
        [ "$total" -le 180 ] || fail "seed $seed $paper $1 $2: keys $total pages, more than 6 a key on average"
        [ "$seed" -ne 1 ] || [ "$total" -le "$most" ] || fail "seed 1 $paper $1 $2: keys $total pages (at most $most)"
      fi
    done
  done
done
[ $status -eq 0 ] && echo "page budget: ok"
exit $status
