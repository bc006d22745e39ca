#!/usr/bin/env bash
# The explorer in headless Chromium (explore_test.mjs): epure.solve against `epure solve` on
# the adversarial lines (tests/tools/adversarial_cases.py, fixed seed, and the kept ones of
# tests/solve/), decimal-degenerate figures (tests/tools/decimal_cases.py) and the contract's examples; every view dragged, by mouse, touch and keyboard;
# a set's links; lines decided by digits beyond a double's, shown; timings. Needs `npm ci` in tests/browser (the bootstrap does it in test mode).
# Screenshots and timings.json go to $EPURE_BROWSER_OUT (default: a temporary directory).
set -u
here=$EPURE_SOURCE_DIR/tests
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
out=${EPURE_BROWSER_OUT:-$tmp/shots}
[ -d "$here/browser/node_modules/puppeteer-core" ] || { echo "FAIL: run 'npm ci' in tests/browser first"; exit 1; }

python3 "$here/tools/adversarial_cases.py" "${EPURE_ADVERSARIAL_SEED:-20240611}" "${EPURE_BROWSER_LINES:-2000}" >"$tmp/lines.jsonl" || exit 1
cat "$here/solve/adversarial.input.jsonl" "$here/solve/examples/solve.input.jsonl" >>"$tmp/lines.jsonl"
# figures degenerate as the decimals written, not as their doubles (one meaning for a number)
python3 "$here/tools/decimal_cases.py" 35 700 >>"$tmp/lines.jsonl" || exit 1
# the generator has few vectors lines: 300 more, from integers to extreme and subnormal scales
python3 - >>"$tmp/lines.jsonl" <<'PY'
import json, random
r = random.Random(17)
def x():
    k = r.random()
    if k < 0.3: return r.randint(-9, 9)
    if k < 0.6: return round(r.uniform(-10, 10), 2)
    if k < 0.9: return r.uniform(-1, 1) * 10.0 ** r.randint(-300, 300)
    return r.choice([5e-324, -5e-324, 1e-310, 1.7e308, -0.0, 0.0])
for _ in range(300):
    print(json.dumps({"kind": "vectors", "u": [x(), x()], "v": [x(), x()]}))
PY
# the lines epure solves: blank ones are skipped (explore_test.mjs drops them too)
grep -v -E $'^[ \t]*\r?$' "$tmp/lines.jsonl" | sed $'s/\r$//' >"$tmp/solve.jsonl"
"$EPURE" solve "$tmp/solve.jsonl" >"$tmp/expected.jsonl" 2>/dev/null
[ $? -le 1 ] || { echo "FAIL: epure solve"; exit 1; }

# lines decided by digits beyond a double's 17 (and one whose extra digits decide nothing): their
# views must carry the digits written and never give another verdict than epure solve's
cat >"$tmp/long.jsonl" <<'JSONL'
{"kind":"segments","A":[0,0],"B":[3,1],"C":[0,1],"D":[0.37037036703703703673,1.12345678901234567891]}
{"kind":"segments","A":[0,0],"B":[3,3],"C":[1,0],"D":[2,1.0000000000000000000001]}
{"kind":"segments","A":[0,0],"B":[3,1],"C":[0,1],"D":[0.37037036703703703673,1.123456789012345678915]}
{"kind":"vectors","u":[8.44,3.98,-7.98],"v":[33.76,15.92,-3.19199999999999999996624e1]}
{"kind":"ray_square","A":[-9.999999999999999999999999e-1,-0.9],"u":[0.8,-0.08]}
{"kind":"vectors","u":[0.1000000000000000055511151231257827,0.3],"v":[1,3]}
{"kind":"projection","A":[0,0],"B":[2,0],"C":[1.00000000000000000001,5]}
JSONL
"$EPURE" solve "$tmp/long.jsonl" >"$tmp/long.expected" || { echo "FAIL: epure solve (long digits)"; exit 1; }
cat "$tmp/long.jsonl" >>"$tmp/solve.jsonl"
cat "$tmp/long.expected" >>"$tmp/expected.jsonl"

"$EPURE" explore --out "$tmp/page" >/dev/null || { echo "FAIL: epure explore"; exit 1; }
"$EPURE" generate --format svg --sheets 2 --seed 3 --jobs 1 --quiet --out "$tmp/set" || { echo "FAIL: epure generate"; exit 1; }
[ -f "$tmp/set/explore.html" ] || { echo "FAIL: epure generate wrote no explore.html"; exit 1; }

node "$here/browser/explore_test.mjs" "$tmp/page/explore.html" "$tmp/solve.jsonl" "$tmp/expected.jsonl" "$tmp/set" "$out" \
  "$tmp/long.jsonl" "$tmp/long.expected"
