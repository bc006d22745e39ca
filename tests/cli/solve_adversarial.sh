#!/usr/bin/env bash
# `epure solve` against an independent exact-arithmetic reference (tests/tools/reference_solve.py)
# on a few thousand adversarial lines (tests/tools/adversarial_cases.py, fixed seed) and on the
# hand-kept lines of tests/solve/adversarial.input.jsonl: every result agrees by the acceptance
# rules (compare_jsonl.py), the exit status is 1 exactly when some line is bad, there is one output
# line per non-blank input line, and one stderr line per bad line. Decisions must be the exact
# ones and every number within 4 ulps of the figure's scale (compare_jsonl.py --ulps 4: the
# contract's bound, geometry's printed_values for ray/circle and ray/sphere, turned_written's
# double-double check for turned ellipses and rectangles at any angle).
#
# Another seed or size: EPURE_ADVERSARIAL_SEED=7 EPURE_ADVERSARIAL_LINES=20000 ctest -R adversarial
set -u
here=$EPURE_SOURCE_DIR/tests
tools=$here/tools
seed=${EPURE_ADVERSARIAL_SEED:-20240611}
count=${EPURE_ADVERSARIAL_LINES:-3000}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

# The lines epure solves: split on '\n', a trailing '\r' dropped, blank (spaces, tabs) skipped.
nonblank() { grep -c -v -E $'^[ \t]*\r?$' "$1"; }

check() {  # check NAME INPUT EXPECTED
  local name=$1 input=$2 expected=$3
  "$EPURE" solve "$input" >"$tmp/$name.out" 2>"$tmp/$name.err"
  local status=$? bad want
  bad=$(grep -c '^{"error"' "$expected")
  want=$([ "$bad" -gt 0 ] && echo 1 || echo 0)
  [ "$status" -eq "$want" ] || fail "$name: exit status $status, expected $want ($bad bad lines)"
  [ "$(wc -l <"$tmp/$name.out")" -eq "$(nonblank "$input")" ] ||
    fail "$name: $(wc -l <"$tmp/$name.out") output lines for $(nonblank "$input") non-blank input lines"
  [ "$(wc -l <"$tmp/$name.err")" -eq "$bad" ] ||
    fail "$name: $(wc -l <"$tmp/$name.err") stderr lines for $bad bad lines"
  python3 "$tools/compare_jsonl.py" "$tmp/$name.out" "$expected" --input "$input" --ulps 4 \
    >"$tmp/$name.cmp" ||
    fail "$name: results disagree with the reference:"$'\n'"$(head -n 300 "$tmp/$name.cmp")"
  grep '^measured' "$tmp/$name.cmp"
  echo "$name: $(tail -n 1 "$tmp/$name.cmp")"
}

# 1. Generated: seed $seed, $count lines.
python3 "$tools/adversarial_cases.py" "$seed" "$count" >"$tmp/generated.jsonl" || { echo "generator failed"; exit 1; }
python3 "$tools/reference_solve.py" "$tmp/generated.jsonl" >"$tmp/generated.expected"
[ $? -le 1 ] || { echo "reference failed"; exit 1; }
check generated "$tmp/generated.jsonl" "$tmp/generated.expected"

# The same lines through standard input give the same bytes.
"$EPURE" solve <"$tmp/generated.jsonl" >"$tmp/stdin.out" 2>/dev/null
cmp -s "$tmp/generated.out" "$tmp/stdin.out" || fail "stdin output differs from file output"

# 2. Kept lines, each a case that once went wrong or nearly: the committed expected output must
# still be the reference's (if the reference changed on purpose, regenerate it with
#   python3 tests/tools/reference_solve.py tests/solve/adversarial.input.jsonl \
#     > tests/solve/adversarial.expected.jsonl
# and review the diff), then epure must agree with it.
kept=$here/solve/adversarial
python3 "$tools/reference_solve.py" "$kept.input.jsonl" >"$tmp/kept.reference"
cmp -s "$tmp/kept.reference" "$kept.expected.jsonl" ||
  fail "the reference no longer reproduces $kept.expected.jsonl"
check kept "$kept.input.jsonl" "$kept.expected.jsonl"

[ "$failed" -eq 0 ] && echo "solve adversarial: ok"
exit "$failed"
