#!/usr/bin/env bash
# The contract's vectors with three components (issue 13): `epure solve` agrees with the exact
# reference (tests/tools/reference_solve.py, which wrote tests/solve/vectors_3d.expected.jsonl),
# bad lines (a zero vector, a 2D v beside a 3D u) refused, and the 2D form unchanged.
set -u
here=$EPURE_SOURCE_DIR/tests
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$EPURE" solve "$here/solve/vectors_3d.input.jsonl" >"$tmp/out.jsonl" 2>"$tmp/err"
[ $? -eq 1 ] || { echo "expected exit status 1 (two bad lines)"; exit 1; }
python3 "$here/tools/compare_jsonl.py" "$tmp/out.jsonl" "$here/solve/vectors_3d.expected.jsonl" || exit 1
python3 "$here/tools/reference_solve.py" "$here/solve/vectors_3d.input.jsonl" | cmp -s - "$here/solve/vectors_3d.expected.jsonl" ||
  { echo "the reference no longer gives vectors_3d.expected.jsonl"; exit 1; }
[ "$(grep -c 'vectors_3d.input.jsonl:[0-9]*: ' "$tmp/err")" -eq 2 ] || { cat "$tmp/err"; exit 1; }
out=$(echo '{"kind":"vectors","u":[3,4],"v":[-4,3]}' | "$EPURE" solve)
[ "$out" = '{"kind":"vectors","dot":0,"cross":25,"norm_u":5,"norm_v":5,"cos":0,"sin":1,"angle_deg":90}' ] ||
  { echo "2D form changed: $out"; exit 1; }
echo "solve vectors 3D: ok"
