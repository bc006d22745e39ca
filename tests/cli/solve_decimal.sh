#!/usr/bin/env bash
# One meaning for a number (issue 35): `epure solve` against the exact reference, which reads
# every number as the fraction its text writes, on figures degenerate as decimals and not as
# their doubles (tests/tools/decimal_cases.py: parallel, collinear, t = 0 or 1, a projection foot
# on an end, tangent rays, origins on the circle or sphere, rays through a corner or along a side
# of the square and cube, vectors parallel as written, at scales 1e-8 to 1e8). Every decision
# must be the exact one and every number within 4 ulps (compare_jsonl.py --ulps 4).
# Another seed or size: EPURE_DECIMAL_SEED=7 EPURE_DECIMAL_LINES=20000 ctest -R solve_decimal
set -u
tools=$EPURE_SOURCE_DIR/tests/tools
seed=${EPURE_DECIMAL_SEED:-35}
count=${EPURE_DECIMAL_LINES:-4500}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
python3 "$tools/decimal_cases.py" "$seed" "$count" >"$tmp/in.jsonl" || { echo "FAIL: generator"; exit 1; }
python3 "$tools/reference_solve.py" "$tmp/in.jsonl" >"$tmp/expected" || { echo "FAIL: reference"; exit 1; }
"$EPURE" solve "$tmp/in.jsonl" >"$tmp/out" || { echo "FAIL: epure solve refused a line"; exit 1; }
python3 "$tools/compare_jsonl.py" "$tmp/out" "$tmp/expected" --input "$tmp/in.jsonl" --ulps 4 >"$tmp/cmp" ||
  { head -n 100 "$tmp/cmp"; echo "FAIL: results disagree with the reference"; exit 1; }
grep '^measured' "$tmp/cmp"
echo "decimal lines: $(tail -n 1 "$tmp/cmp")"
# The issue's example: parallel as written.
echo '{"kind":"segments","A":[9.217,-2.43],"B":[8.593,-1.674],"C":[8.547,-2.17],"D":[7.247,-0.595]}' |
  "$EPURE" solve | grep -q '"reason":"parallel"' || { echo "FAIL: the issue's example is not parallel"; exit 1; }
# The exact arithmetic's cases (tests/geometry/decimal_arithmetic_test.cpp) are still the ones
# Python's exact integers and fractions write.
python3 "$tools/decimal_arithmetic.py" 35 200 | cmp -s - "$EPURE_SOURCE_DIR/tests/geometry/decimal_arithmetic.txt" ||
  { echo "FAIL: decimal_arithmetic.py no longer writes tests/geometry/decimal_arithmetic.txt"; exit 1; }
echo "solve decimal: ok"
