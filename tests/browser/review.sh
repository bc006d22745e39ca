#!/usr/bin/env bash
# epure scan's review.html in headless Chromium (review_test.mjs), then the corrections it saved
# applied by `epure scan --corrections` (nothing left to review, the typed values in answers.json)
# and by `epure grade --corrections` (the typed values graded).
# Needs `npm ci` in tests/browser and src/scan/classifier (the bootstrap does both in test mode).
set -u
here=$EPURE_SOURCE_DIR/tests
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
out=${EPURE_BROWSER_OUT:-$tmp/review}
[ -d "$here/browser/node_modules/puppeteer-core" ] || { echo "FAIL: run 'npm ci' in tests/browser first"; exit 1; }
"$EPURE" generate --format pdf --sheets 2 --seed 4 --lang fr --jobs 1 --quiet --out "$tmp/set" || { echo "FAIL: epure generate"; exit 1; }
"$EPURE_SCAN_FIXTURE" --key "$tmp/set/key.json" --set "$tmp/set" --out "$tmp/scans" --sheets 2 --dpi 150 --degrade copier --format png --seed 2 >/dev/null || { echo "FAIL: fixture"; exit 1; }
"$EPURE" scan "$tmp"/scans/scan-*.png --key "$tmp/set/key.json" --layout "$tmp/scans/layout.json" --out "$tmp/out" -q 2>"$tmp/scan.err"
node "$here/browser/review_test.mjs" "$tmp/out/review.html" "$tmp/out/fields.csv" "$out" || exit 1
"$EPURE" scan "$tmp"/scans/scan-*.png --key "$tmp/set/key.json" --layout "$tmp/scans/layout.json" --out "$tmp/out2" \
  --corrections "$out/corrections.json" -q 2>"$tmp/err"
fail=0
left=$(grep -c ',review,' "$tmp/out2/fields.csv")
[ "$left" = 0 ] && echo "ok   no field left to review after the corrections" || { echo "FAIL: $left fields still to review"; fail=1; }
python3 - "$out/corrections.json" "$tmp/out2/answers.json" <<'PY' || fail=1
import json, sys
c = json.load(open(sys.argv[1]))["corrections"]
a = {r["sheet"]: r["answers"] for r in json.load(open(sys.argv[2]))}
bad = [k for k in c if k["question"] != "student_number" and a[k["sheet"]].get(k["question"], "") != k["value"]]
print(("FAIL: " if bad else "ok   ") + f"answers.json holds the {len(c)} corrected values" + (f": {bad[:3]}" if bad else ""))
sys.exit(1 if bad else 0)
PY
# The same file read by `epure grade --corrections` (one format, one reader): applied to the
# answers scan wrote before the corrections, every typed value is the answer graded.
"$EPURE" grade --key "$tmp/set/key.json" --answers "$tmp/out/answers.json" --corrections "$out/corrections.json" \
  --json "$tmp/marks.json" -q 2>"$tmp/grade.err"
python3 - "$out/corrections.json" "$tmp/marks.json" "$tmp/grade.err" <<'PY' || fail=1
import json, sys
c = json.load(open(sys.argv[1]))["corrections"]
given = {(s["sheet"], q["id"]): q["given"] for s in json.load(open(sys.argv[2]))["submissions"] for q in s["questions"]}
said = [l for l in open(sys.argv[3]) if "corrections.json" in l]
# a value typed empty is a blank answer: graded as none given (null)
bad = [k for k in c if k["question"] != "student_number" and (given.get((k["sheet"], k["question"])) or "") != k["value"]]
print(("FAIL: " if bad or said else "ok   ") + f"epure grade --corrections applies the {len(c)} saved values" +
      (f": {bad[:3]}" if bad else "") + (f"; it says: {said[:2]}" if said else ""))
sys.exit(1 if bad or said else 0)
PY
# under the sanitizers a report ends a run with exit status 1, as fields to review do
reports=$(grep -l -a -e "ERROR: AddressSanitizer" -e "ERROR: LeakSanitizer" -e "runtime error:" "$tmp"/*.err 2>/dev/null)
[ -z "$reports" ] && echo "ok   no sanitizer report" || { echo "FAIL: sanitizer reports in: $reports"; fail=1; }
exit $fail
