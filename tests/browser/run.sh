#!/usr/bin/env bash
# The explorer in headless Chromium (explore_test.mjs): epure.solve against `epure solve` on
# the adversarial lines (tests/tools/adversarial_cases.py, fixed seed, and the kept ones of
# tests/solve/), decimal-degenerate figures (tests/tools/decimal_cases.py) and the contract's examples; every view dragged, by mouse, touch and keyboard;
# a set's links; timings. Needs `npm ci` in tests/browser (the bootstrap does it in test mode).
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

"$EPURE" explore --out "$tmp/page" >/dev/null || { echo "FAIL: epure explore"; exit 1; }
"$EPURE" generate --format svg --sheets 2 --seed 3 --jobs 1 --quiet --out "$tmp/set" || { echo "FAIL: epure generate"; exit 1; }
[ -f "$tmp/set/explore.html" ] || { echo "FAIL: epure generate wrote no explore.html"; exit 1; }

node "$here/browser/explore_test.mjs" "$tmp/page/explore.html" "$tmp/solve.jsonl" "$tmp/expected.jsonl" "$tmp/set" "$out"
