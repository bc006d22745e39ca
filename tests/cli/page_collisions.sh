#!/usr/bin/env bash
# No text over text on any printed page: the class-set PDFs of many seeds (every kind of the
# course and, over the seeds, its branches), both languages, every difficulty, A4 and Letter,
# sheets and keys, checked word by word with pdftotext -bbox (tests/tools/page_collisions.py: an
# overlap of more than 1 pt both across and down is a collision), and a class's feedback sheets.
# 144 sheets and their keys, about 1,900 pages; the sets are generated two at a time (about 30 s
# on two cores).
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
for tool in pdftotext python3; do command -v $tool >/dev/null || fail "$tool missing (see .ci/bootstrap)"; done
checker=$EPURE_SOURCE_DIR/tests/tools/page_collisions.py
export SOURCE_DATE_EPOCH=1700000000

sets=()
seed=100
for lang in en fr; do
  for difficulty in easy standard hard; do
    for paper in a4 letter; do
      sets+=("$lang $difficulty $paper $seed")
      seed=$((seed + 1))
    done
  done
done
run_set() {
  set -- $1
  "$EPURE" generate --quiet --format pdf --sheets 12 --seed "$4" --lang "$1" --difficulty "$2" \
    --paper "$3" --jobs 1 --out "$tmp/$1-$2-$3" || echo "generate failed: $*" > "$tmp/$1-$2-$3.failed"
}
i=0
for s in "${sets[@]}"; do
  run_set "$s" &
  i=$((i + 1))
  [ $((i % 2)) -eq 0 ] && wait
done
wait
ls "$tmp"/*.failed >/dev/null 2>&1 && fail "$(cat "$tmp"/*.failed)"
# The feedback sheets of a marked class (tests/grading/data), in both languages.
data=$EPURE_SOURCE_DIR/tests/grading/data
for lang in en fr; do
  "$EPURE" grade --key "$data/key_small.json" --answers "$data/export_fr.csv" --report "$tmp/marks-$lang.csv" \
    --feedback "$tmp/feedback-$lang" --lang "$lang" -q || fail "grade --lang $lang"
done
python3 "$checker" "$tmp"/*/sheets.pdf "$tmp"/*/keys.pdf "$tmp"/feedback-*/*.pdf || fail "text printed over text (above)"
echo "page collisions: ok"
