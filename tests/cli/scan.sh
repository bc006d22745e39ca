#!/usr/bin/env bash
# epure scan end to end, on the suite's own scans of the sheets `epure generate` printed
# (tests/scan/scan_fixture_main.cpp --set: a French set's sheets.pdf rendered, handwritten digits
# held out of the classifier's training written into the comb cells its layout.json names, ticks
# of several kinds into its boxes, degraded as a copier does):
#  - every input page in pages.csv with its status: the blank page, the page of another set, the
#    duplicate said, the dropped page said missing, every other page identified;
#  - the figures (tests/tools/scan_figures.py): silent errors and fields sent to review within
#    their bounds, ticks right or sent to review;
#  - answers.json marked by `epure grade`: every value read is marked right (the suite wrote the
#    key's values);
#  - a corrections file settling the fields sent to review: scan again with it, nothing left;
#  - bad input: a corrupt PDF, a file of no image, an image of no page, a key of another set.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
ok() { echo "ok   $*"; }
bad() { echo "FAIL $*"; fail=1; }
tools=$EPURE_SOURCE_DIR/tests/tools

"$EPURE" generate --format pdf --sheets 4 --seed 5 --lang fr --jobs 1 --quiet --out "$tmp/set" || { bad "generate"; exit 1; }
key=$tmp/set/key.json
# The bounds pinned on these small stacks (about 195 fields, 400 digits each), as measured with
# the committed classifier: three networks of depth 2 (two convolutions a stage) trained on
# MNIST's 58,004 digits, a second look from seven crops at cells read under 0.90, the sign cell
# read as a minus or nothing, cells below 0.82 sent to review, a heavily inked tick box told by its
# shape (2026-12-06, afternoon): silent errors 0 on each stack; fields sent to review 3.1 % (JPEG
# PDF), 7.6 % (bilevel), 3.5 % (300 dpi), 5.6 % (150 dpi; 6.6 % when two heavy crosses went to
# review); digits 99.0-99.8 %. Before (a second look from five crops, no sign-cell reading):
# 3.1, 8.6, 4.0 and 7.1 %; before that (no second look, below 0.85): the same but 4.5 % at 300 dpi
# and 6.6 % at 150 dpi; before that (three networks of depth 1, cells below 0.80): silent 0,
# review 3.1-11.6 %, digits 98.3-99.8 %. On stacks of 24 sheets (README, "epure scan") the
# issue's figures are met on five samples of four stacks: silent errors 0.02-0.09 %, digits
# 99.40-99.65 %, fields to review 4.50-4.90 %.
# Digits: about 400 a stack, so one standard deviation of the rate is 0.55 %; the bilevel stack's
# rate is 98.8-99.2 % on 24 sheets with the depth-1 networks (bench/scan_accuracy.sh, two
# samples): the bound is two deviations under the lower, not a figure one draw happened to reach.
# Ticks (about 47 a stack, one in four a light pen's cross at 40 % ink, read as ticked since
# 2026-12-06): none sent to review; bound 4 (heavy crosses at 150 dpi sent 0-2 until they were
# told from fills by their shape; before that, every light cross went, about 12 a stack). Fields to review: bound 12 %, the bilevel stack's
# 7.6 % with a margin (the depth-1 networks sent 11.6 %: under it, but not the 5 % together below).
max_tick_review=${EPURE_SCAN_MAX_TICK_REVIEW:-0.09}
max_silent=${EPURE_SCAN_MAX_SILENT:-0.008}
max_review=${EPURE_SCAN_MAX_REVIEW:-0.12}
min_digits=${EPURE_SCAN_MIN_DIGITS:-0.977}

# Four stacks: a copier's JPEG PDF (shuffled, a page dropped, one twice, a blank one, one of
# another set), a bilevel TIFF (CCITT G4, 200 dpi), a Flate PDF at 300 dpi, PNG at 150 dpi.
i=0
for spec in "pdf copier 200 --mess" "tiff-g4 bilevel 200" "pdf-flate copier 300" "png copier 150"; do
  set -- $spec
  i=$((i + 1))
  d=$tmp/s$i
  "$EPURE_SCAN_FIXTURE" --key "$key" --set "$tmp/set" --out "$d" --sheets 4 --format "$1" --degrade "$2" --dpi "$3" --seed $((40 + i)) ${4:-} >/dev/null ||
    { bad "fixture $spec"; continue; }
  "$EPURE" scan "$d"/scan* --key "$key" --layout "$d/layout.json" --out "$d/out" -q 2>"$d/err"
  status=$?
  [ "$status" -le 1 ] || bad "$spec: scan exit status $status: $(cat "$d/err")"
  python3 "$tools/scan_figures.py" "$d/truth.json" "$d/out" "$d/layout.json" --check --max-silent "$max_silent" --max-review "$max_review" --max-tick-review "$max_tick_review" --min-digits "$min_digits" >"$d/figures.json" 2>"$d/figures.err" &&
    ok "$spec: figures within bounds: $(python3 -c "import json,sys; f=json.load(open(sys.argv[1])); print(f'{f[\"fields\"]} fields, {f[\"silent\"]} silent errors, {f[\"review\"]} to review, ticks {f[\"tick_right\"]}+{f[\"tick_review\"]}/{f[\"tick_fields\"]}, digits {f[\"digit_cells_right\"]}/{f[\"digit_cells\"]}')" "$d/figures.json")" ||
    bad "$spec: $(cat "$d/figures.err")"
  # every input page listed; the expected statuses
  pages=$(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['pages']))" "$d/truth.json")
  listed=$(($(wc -l <"$d/out/pages.csv") - 1))
  [ "$listed" = "$pages" ] && ok "$spec: every input page in pages.csv ($pages)" || bad "$spec: $listed pages in pages.csv for $pages"
  if [ "${4:-}" = --mess ]; then
    for s in blank "another set" duplicate; do
      grep -q ",$s," "$d/out/pages.csv" && ok "$spec: a page '$s'" || bad "$spec: no page '$s' in pages.csv"
    done
    dropped=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['dropped'])" "$d/truth.json")
    sheet=${dropped% p*}; page=${dropped##* p}
    grep -q "sheet $sheet: page $page of .* is missing" "$d/err" && ok "$spec: dropped page said missing ($dropped)" || bad "$spec: the dropped page $dropped is not said missing"
    others=$(grep -v -E ",(identified|blank|another set|duplicate)," "$d/out/pages.csv" | tail -n +2)
    [ -z "$others" ] && ok "$spec: every other page identified" || bad "$spec: pages not identified: $others"
  else
    others=$(grep -v ",identified," "$d/out/pages.csv" | tail -n +2)
    [ -z "$others" ] && ok "$spec: every page identified" || bad "$spec: pages not identified: $others"
  fi
done

# The four stacks together (788 fields, 1,622 digits): the issue's figures (measured 2026-12-06,
# afternoon: digits 99.45 %, silent errors 0, ticks 186 right of 186, fields to review 39, 4.95 %).
# These stacks are one deterministic draw and the 5 % bound leaves no field to spare (39 is the
# most it lets through: a 40th is 5.08 %). On the larger samples of bench/scan_accuracy.sh the
# rate is 4.50-4.90 %: a change that sends more fields to review here is to be measured there,
# not loosened here.
# Before: 5.2 % (two heavy crosses to review), 5.7 % (a second look from five crops), 7.2 % (the
# depth-1 networks), pinned at 6 % until the ticks were told by their shape.
python3 - "$tmp"/s1/figures.json "$tmp"/s2/figures.json "$tmp"/s3/figures.json "$tmp"/s4/figures.json <<'PY' && ok "the four stacks together: the issue's digits, silent errors, ticks and fields to review (5 %)" || fail=1
import json, sys
t = {}
for path in sys.argv[1:]:
    for k, v in json.load(open(path)).items():
        if isinstance(v, (int, float)) and not isinstance(v, bool):
            t[k] = t.get(k, 0) + v
digits = t["digit_cells_right"] / t["digit_cells"]
silent = t["silent"] / t["fields"]
tick_wrong = t["tick_silent"]  # a tick read wrong and not sent to review
print(f"together: {t['fields']} fields, digits {digits:.4f}, silent {t['silent']} ({silent:.4f}), "
      f"to review {t['review']} ({t['review'] / t['fields']:.4f}), ticks {t['tick_right']} right, {t['tick_review']} to review, {tick_wrong} wrong")
problems = []
if digits < 0.99: problems.append(f"digits read right {digits:.4f} < 0.99")
if silent > 0.001: problems.append(f"silent errors {silent:.4f} > 0.001")
if t["review"] > 0.05 * t["fields"]: problems.append(f"fields to review {t['review'] / t['fields']:.4f} > 0.05")
# ticks: none wrong; read right 186 of 186 (their 99.9 % cannot be resolved on 186 ticks: one to
# review is 0.5 %, so at most one; on the 24-sheet samples 99.91-100 % right, 0-1 to review of 1,130)
if tick_wrong > 0 or t["tick_right"] < 0.99 * t["tick_fields"]: problems.append(f"ticks: {tick_wrong} wrong, {t['tick_right']} of {t['tick_fields']} right")
if problems:
    print("FAIL the four stacks together: " + "; ".join(problems))
    sys.exit(1)
PY

# The loop: grade marks what scan read; every value read as written is right (the suite wrote
# the key's); a value marked wrong is one of the silent errors (read, not as written) that
# scan_figures counts and bounds above.
d=$tmp/s1
"$EPURE" grade --key "$key" --answers "$d/out/answers.json" --json "$d/marks.json" -q 2>"$d/grade.err"
[ $? -le 1 ] || bad "grade: $(cat "$d/grade.err")"
python3 - "$d/out/answers.json" "$d/marks.json" "$d/truth.json" <<'PY' && ok "grade: every value scan read as written is marked right" || fail=1
import json, sys
norm = lambda v: str(v).replace("−", "-").replace(",", ".").strip()
answers = {r["sheet"]: r["answers"] for r in json.load(open(sys.argv[1]))}
marks = json.load(open(sys.argv[2]))
truth = json.load(open(sys.argv[3]))["sheets"]
wrong, silent, n = [], 0, 0
for sub in marks["submissions"]:
    given = answers.get(sub["sheet"], {})
    written = truth[sub["sheet"]]["answers"]
    for m in sub["questions"]:
        if m["id"] in given:
            n += 1
            if m["verdict"] not in ("right", "follow_through"):
                if norm(given[m["id"]]) != norm(written.get(m["id"])):
                    silent += 1
                else:
                    wrong.append((sub["sheet"], m["id"], given[m["id"]], m["verdict"]))
if wrong or n == 0:
    print(f"FAIL grade: {len(wrong)} of {n} values read as written are marked wrong: {wrong[:5]}")
    sys.exit(1)
print(f"grade: {n} values read, {silent} of them misread (silent errors) and marked wrong")
PY

# Corrections: the fields sent to review settled with what was written, scanned again.
python3 - "$d/truth.json" "$d/out/fields.csv" >"$tmp/corrections.json" <<'PY'
import csv, json, sys
truth = json.load(open(sys.argv[1]))["sheets"]
out = []
for r in csv.DictReader(open(sys.argv[2])):
    if r["status"] == "review":
        t = truth[r["sheet"]]
        v = t["student_number"] if r["question"] == "student_number" else t["answers"].get(r["question"], "")
        out.append({"sheet": r["sheet"], "question": r["question"], "value": v, "note": "suite"})
print(json.dumps({"format": "epure-corrections", "version": 1, "corrections": out}))
PY
"$EPURE" scan "$d"/scan* --key "$key" --layout "$d/layout.json" --out "$d/out2" --corrections "$tmp/corrections.json" --crops -q 2>"$tmp/scan2.err"
silent1=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['silent'])" "$d/figures.json")
python3 "$tools/scan_figures.py" "$d/truth.json" "$d/out2" --check --max-silent "$max_silent" --max-review 0 >"$tmp/c.json" 2>"$tmp/c.err" &&
  [ "$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['silent'])" "$tmp/c.json")" = "$silent1" ] &&
  ok "corrections: nothing left to review, no wrong value but the $silent1 silent errors" || bad "corrections: $(cat "$tmp/c.err")"
grep -q ",corrected," "$d/out2/fields.csv" && ok "corrections: fields.csv says which were corrected" || bad "corrections: no field marked corrected"

# The loop: the scanned and corrected answers get the marks of the answers that were written
# (truth.json, on the pages scanned: one was dropped), sheet by sheet, as `epure grade` gives them.
python3 - "$d/truth.json" "$d/out2/fields.csv" >"$tmp/written.json" <<'PY'
import csv, json, sys
truth = json.load(open(sys.argv[1]))["sheets"]
scanned = {(r["sheet"], r["question"]) for r in csv.DictReader(open(sys.argv[2]))}
print(json.dumps([{"sheet": s, "answers": {q: v for q, v in t["answers"].items() if (s, q) in scanned}} for s, t in truth.items()]))
PY
"$EPURE" grade --key "$key" --answers "$tmp/written.json" --json "$tmp/marks_written.json" -q 2>"$tmp/grade1.err"
"$EPURE" grade --key "$key" --answers "$d/out2/answers.json" --corrections "$tmp/corrections.json" --json "$tmp/marks_scanned.json" --feedback "$tmp/fb" -q 2>"$tmp/grade2.err"
# --crops: every field of every page read has its crop; grade finds them beside answers.json
# and each feedback sheet shows them (SVG: inline PNGs; PDF: image objects), one per question
# scanned on that sheet
python3 - "$d/out2" "$tmp/fb" <<'PY' && ok "crops: every field read has its crop, and the feedback sheets show one under each question scanned" || fail=1
import csv, os, re, subprocess, sys
out, fb = sys.argv[1], sys.argv[2]
fields = [r for r in csv.DictReader(open(os.path.join(out, "fields.csv"))) if r["question"] != "student_number"]
missing = [(r["sheet"], r["question"]) for r in fields if not os.path.isfile(os.path.join(out, "crops", r["sheet"], r["question"] + ".png"))]
if not fields or missing:
    print(f"FAIL crops: {len(missing)} of {len(fields)} fields without a crop: {missing[:5]}")
    sys.exit(1)
per_sheet = {}
for r in fields:
    per_sheet[r["sheet"]] = per_sheet.get(r["sheet"], 0) + 1
problems = []
for sheet, n in per_sheet.items():
    svg = open(os.path.join(fb, sheet + ".svg")).read()
    images = len(re.findall(r'<image [^>]*href="data:image/png;base64,', svg))
    listed = subprocess.run(["pdfimages", "-list", os.path.join(fb, sheet + ".pdf")], capture_output=True, text=True).stdout
    in_pdf = max(0, len(listed.strip().splitlines()) - 2)
    # the crops of questions the sheet's branch does not ask have no feedback line
    if not (0 < images <= n and images == in_pdf):
        problems.append((sheet, n, images, in_pdf))
if problems:
    print(f"FAIL crops: feedback sheets (sheet, fields scanned, SVG images, PDF images): {problems[:5]}")
    sys.exit(1)
PY
python3 - "$tmp/marks_written.json" "$tmp/marks_scanned.json" "$tmp/c.json" "$key" <<'PY' && ok "the loop: scanned and corrected, every sheet gets the written answers' marks (but where a silent error is)" || fail=1
import json, sys
subs = lambda f: {s["sheet"]: s for s in json.load(open(f))["submissions"]}
written, scanned = subs(sys.argv[1]), subs(sys.argv[2])
# a silent error changes its question's mark, and may change the follow-through of the questions
# of its exercise after it
exercise = {(s["id"], q["id"]): e["n"] for s in json.load(open(sys.argv[4]))["sheets"] for e in s["exercises"] for q in e["questions"]}
silent_q = {(e["sheet"], e["question"]) for e in json.load(open(sys.argv[3]))["silent_errors"]}
silent = {(s, exercise.get((s, q))) for s, q in silent_q}
if not written or written.keys() != scanned.keys():
    print(f"FAIL the loop: sheets marked {sorted(written)} != {sorted(scanned)}")
    sys.exit(1)
bad, changed = [], set()
for sheet, w in written.items():
    v = {q["id"]: (q["verdict"], q.get("points")) for q in w["questions"]}
    s = {q["id"]: (q["verdict"], q.get("points")) for q in scanned[sheet]["questions"]}
    for q in v.keys() | s.keys():
        if v.get(q) != s.get(q):
            if (sheet, exercise.get((sheet, q))) in silent:
                changed.add(sheet)
            else:
                bad.append((sheet, q, v.get(q), s.get(q)))
    if sheet not in changed and (w["score"], w["to_check"]) != (scanned[sheet]["score"], scanned[sheet]["to_check"]):
        bad.append((sheet, "score", w["score"], scanned[sheet]["score"]))
if bad:
    print(f"FAIL the loop: marks of the written answers differ from the scanned ones: {bad[:5]}")
    sys.exit(1)
print(f"the loop: {len(written)} sheets, the same marks question by question; {len(silent_q)} silent errors change {len(changed)} sheets' marks")
PY

# Bad input: each named with its file and page, the rest still read.
head -c 3000 "$tmp/s3/scans.pdf" >"$tmp/corrupt.pdf"
echo "not an image" >"$tmp/notes.txt"
python3 - "$tmp/noise.png" <<'PY'
import random, struct, sys, zlib
r = random.Random(5); w, h = 300, 420
raw = b"".join(b"\0" + bytes(r.choice((0, 255)) if r.random() < 0.02 else 255 for _ in range(w)) for _ in range(h))
def chunk(t, d): return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
open(sys.argv[1], "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0)) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
PY
"$EPURE" scan "$tmp/corrupt.pdf" "$tmp/notes.txt" "$tmp/noise.png" "$tmp"/s4/scan-*.png --key "$key" --layout "$tmp/s4/layout.json" --out "$tmp/bad" -q 2>"$tmp/bad.err"
[ $? = 1 ] && ok "bad input: exit status 1" || bad "bad input: exit status not 1"
grep -q "scan: $tmp/corrupt.pdf: page 1: unreadable: " "$tmp/bad.err" && ok "bad input: the corrupt PDF named" || bad "bad input: corrupt PDF: $(cat "$tmp/bad.err")"
grep -q "scan: $tmp/notes.txt: page 1: unreadable: not a PDF, PNG, JPEG or TIFF file" "$tmp/bad.err" && ok "bad input: a text file named" || bad "bad input: text file: $(cat "$tmp/bad.err")"
grep -q "scan: $tmp/noise.png: page 1: unknown: " "$tmp/bad.err" && ok "bad input: an image of no page named" || bad "bad input: noise: $(cat "$tmp/bad.err")"
n=$(grep -c ",identified," "$tmp/bad/pages.csv")
m=$(ls "$tmp"/s4/scan-*.png | wc -l)
[ "$n" = "$m" ] && ok "bad input: the other $m pages still read" || bad "bad input: $n pages identified of $m"
"$EPURE" generate --format svg --sheets 1 --seed 6 --jobs 1 --quiet --out "$tmp/other" || bad "generate another set"
"$EPURE" scan "$tmp"/s4/scan-001.png --key "$tmp/other/key.json" --layout "$tmp/s4/layout.json" --out "$tmp/x" -q 2>"$tmp/x.err"
[ $? = 2 ] && grep -q "is the key of another set" "$tmp/x.err" && ok "a key of another set refused" || bad "key of another set: $(cat "$tmp/x.err")"
sed 's/"version": *1/"version": 9/' "$tmp/s4/layout.json" >"$tmp/layout9.json"
"$EPURE" scan "$tmp"/s4/scan-001.png --key "$key" --layout "$tmp/layout9.json" --out "$tmp/x" -q 2>"$tmp/x.err"
[ $? = 2 ] && grep -q "layout9.json: a layout.json of another version" "$tmp/x.err" && ok "a layout of another version refused" || bad "layout version: $(cat "$tmp/x.err")"
# Under the sanitizers (the ASan run of .ci/bootstrap test) a report ends a run with exit status 1,
# the status of pages or fields to review: every stderr kept above is searched for one.
reports=$(grep -l -a -e "ERROR: AddressSanitizer" -e "ERROR: LeakSanitizer" -e "runtime error:" "$tmp"/*.err "$tmp"/s*/err "$tmp"/s*/*.err 2>/dev/null)
[ -z "$reports" ] && ok "no sanitizer report" || bad "sanitizer reports in: $reports"
exit $fail
