#!/usr/bin/env bash
# `epure grade` on a French class of 10 (seed 5, the course's spec, issue 31): marks a teacher
# can publish.
#   1. harmless input is read, not scored 0: a unit after a number (4,75 cm, 1,04 u), a point in
#      one cell ((x ; y)), "hors segment", t_proj and d² typed in each other's cell;
#   2. what cannot be read is to check: its points held, listed, exit status 1; a corrections
#      file settles it and grade run again gives the full mark and exit status 0;
#   3. item analysis in the JSON report, checked against an independent Python computation
#      (tests/tools/item_analysis.py), and in the French summary with no internal code;
#   4. the class report: HTML that parses, a PDF that qpdf accepts, with the plots, in French;
#   5. marks out of 20 by default for a French set, the gradebook for Moodle from a roster.
# Question ids are taken from key.json (an exercise's "number", else its place), never written
# here: the course names its exercises P, 1, 2, …, 3.3, and a renumbering must not break this.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }
tools="$EPURE_SOURCE_DIR/tests/tools"

"$EPURE" generate --lang fr --sheets 10 --seed 5 --format svg --out "$tmp/set" -q >/dev/null 2>"$tmp/gen.err" \
  || fail "generate: $(cat "$tmp/gen.err")"
python3 "$tools/make_class.py" "$tmp/set/key.json" "$tmp/class.csv" --seed 3 --lang fr || fail "make_class"
# the sheet this test answers: the first of the set whose segments miss each other, whose ray
# hits the circle from outside and meets the square (the cases its answers need); then the ids
# it names, from the key: an exercise by its place, then the field
python3 - "$tmp/set/key.json" >"$tmp/ids.env" <<'PY' || fail "the question ids from key.json"
import json, sys
def cases(s): return {e["n"]: (e["kind"], e["branch"]) for e in s["exercises"]}
want = {3: {("segments", "outside")}, 4: {("ray_circle", "hit")}, 5: {("ray_square", "hit"), ("ray_square", "inside")}}
s = next(s for s in json.load(open(sys.argv[1], encoding="utf-8"))["sheets"]
         if all(cases(s).get(n) in c for n, c in want.items()))
print(f"SHEET_ID={s['id']}")
ids = {q["id"] for e in s["exercises"] for q in e["questions"]}
number = {e["n"]: e.get("number", str(e["n"])) for e in s["exercises"]}
names = {"NORM_U": (1, "norm_u"), "PX": (2, "P.x"), "PY": (2, "P.y"), "REASON": (3, "reason"), "T4": (4, "t"),
         "T_PROJ": (4, "t_proj"), "D2": (4, "d2"), "REASON4": (4, "reason"), "T5": (5, "t")}
for name, (n, field) in names.items():
    id = f"{number[n]}.{field}"
    assert name == "REASON4" or id in ids, (name, id, sorted(ids))   # a hit asks no reason
    print(f"ID_{name}={id}")
PY
. "$tmp/ids.env"
export SHEET_ID ID_NORM_U ID_PX ID_PY ID_REASON ID_T4 ID_T_PROJ ID_D2 ID_REASON4 ID_T5

# 1 and 2: that sheet answered right, typed the ways students type
python3 - "$tmp/set/key.json" "$tmp/harmless.csv" "$tmp/corrections.json" <<'PY' || fail "building the harmless answers"
import csv, json, os, sys
key = json.load(open(sys.argv[1], encoding="utf-8"))
s = next(s for s in key["sheets"] if s["id"] == os.environ["SHEET_ID"])
def right(q):
    e = q["expected"]
    if isinstance(e, bool): return "oui" if e else "non"
    if isinstance(e, list): return " ".join(e) if e else "aucun"
    if isinstance(e, str): return {"outside": "à l’extérieur", "between": "entre A et B", "before": "avant A", "after": "après B"}.get(e, e)
    return f"{round(e, 2):.2f}".replace(".", ",")
cells = {q["id"]: right(q) for e in s["exercises"] for q in e["questions"]}
I = {k[3:]: v for k, v in os.environ.items() if k.startswith("ID_")}
cells[I["NORM_U"]] += " cm"                         # a unit after a number
cells[I["T4"]] += " u"
cells[I["PX"]], cells[I["PY"]] = f"({cells[I['PX']]} ; {cells[I['PY']]})", ""   # a point in one cell
cells[I["REASON"]] = "hors segment"                 # a wording of the course
cells[I["T_PROJ"]], cells[I["D2"]] = cells[I["D2"]], cells[I["T_PROJ"]]        # swapped neighbours
right_t = cells[I["T5"]]
cells[I["T5"]] = right_t.replace(",", ",?")         # a blot: to check
ids = list(cells)
with open(sys.argv[2], "w", encoding="utf-8", newline="") as f:
    w = csv.writer(f, delimiter=";")
    w.writerow(["Feuille", "Étudiant", "Numéro d’étudiant"] + ids)
    w.writerow([s["id"], "Lefèvre, Zoé", "21800001"] + [cells[i] for i in ids])
json.dump({"format": "epure-corrections", "version": 1,
           "corrections": [{"sheet": s["id"], "question": I["T5"], "value": right_t, "note": "lu sur la copie"}]},
          open(sys.argv[3], "w", encoding="utf-8"), ensure_ascii=False)
PY

"$EPURE" grade --key "$tmp/set/key.json" --answers "$tmp/harmless.csv" --json "$tmp/h.json" >"$tmp/h.out" 2>"$tmp/h.err"
st=$?
[ "$st" -eq 1 ] || fail "answers to check: exit $st, expected 1"
grep -qF "$ID_T5" "$tmp/h.err" || fail "the answer to check is not listed on stderr: $(cat "$tmp/h.err")"
python3 - "$tmp/h.json" <<'PY' || fail "harmless input and the answer to check"
import json, os, sys
I = {k[3:]: v for k, v in os.environ.items() if k.startswith("ID_")}
s = json.load(open(sys.argv[1], encoding="utf-8"))["submissions"][0]
q = {x["id"]: x for x in s["questions"]}
for id in (I["NORM_U"], I["T4"], I["PX"], I["PY"], I["REASON"], I["T_PROJ"], I["D2"]):
    assert q[id]["verdict"] == "right", (id, q[id])
assert q[I["PX"]]["read"] == "point_in_one_cell", q[I["PX"]]
assert q[I["T_PROJ"]]["read"] == "swapped_cells" and q[I["T_PROJ"]]["read_from"] == I["D2"], q[I["T_PROJ"]]
assert q[I["T5"]]["verdict"] == "to_check" and q[I["T5"]]["points"] == 0, q[I["T5"]]
assert s["held"] == q[I["T5"]]["max_points"] and s["to_check"] == 1, s
assert s["score"] + s["held"] == s["max"], (s["score"], s["held"], s["max"])   # nothing else lost
assert [f["code"] for f in s["flags"]] == ["to_check", "swapped_cells"], s["flags"]
assert s["student_number"] == "21800001"
assert s["mark"] == round(s["score"] / s["max"] * 20, 2), s["mark"]   # French: out of 20
PY
"$EPURE" grade --key "$tmp/set/key.json" --answers "$tmp/harmless.csv" --json "$tmp/h2.json" \
  --corrections "$tmp/corrections.json" >"$tmp/h2.out" 2>"$tmp/h2.err"
st=$?
[ "$st" -eq 0 ] || fail "settled by the corrections file: exit $st, expected 0 ($(cat "$tmp/h2.err"))"
python3 - "$tmp/h2.json" <<'PY' || fail "settled by the corrections file"
import json, os, sys
t5 = os.environ["ID_T5"]
r = json.load(open(sys.argv[1], encoding="utf-8"))
s = r["submissions"][0]
assert s["score"] == s["max"] and s["held"] == 0 and s["to_check"] == 0, (s["score"], s["max"], s["held"])
assert s["mark"] == 20
q = {x["id"]: x for x in s["questions"]}
assert q[t5]["verdict"] == "right" and q[t5]["corrected"] is True, q[t5]
PY

# 3, 4, 5: the class, with a row of an unknown sheet and an answer not asked
cp "$tmp/class.csv" "$tmp/class2.csv"
python3 - "$tmp/class2.csv" "$tmp/roster.csv" <<'PY'
import csv, os, sys
rows = list(csv.reader(open(sys.argv[1], encoding="utf-8"), delimiter=";"))
h = rows[0]
extra = [""] * len(h)
extra[0], extra[1] = "2000-0005-00ZZ", "Inconnu"
rows.append(extra)
# the circle's reason is not asked of a hit (the sheet chosen above)
row = next(r for r in rows[1:] if r[0] == os.environ["SHEET_ID"])
row[h.index(os.environ["ID_REASON4"])] = "manqué"
csv.writer(open(sys.argv[1], "w", encoding="utf-8", newline=""), delimiter=";").writerows(rows)
with open(sys.argv[2], "w", encoding="utf-8", newline="") as f:
    f.write("Nom;Prénom;N° étudiant;Courriel\n")
    for i in range(1, 11):
        f.write(f"Étudiant;{i:02d};2180{i:04d};e{i:02d}@univ.fr\n")
    f.write("Absent;Abel;21809999;abel@univ.fr\n")
PY
"$EPURE" grade --key "$tmp/set/key.json" --answers "$tmp/class2.csv" --json "$tmp/class.json" --report "$tmp/report.csv" \
  --class-report "$tmp/cr" --gradebook moodle "$tmp/moodle.csv" --roster "$tmp/roster.csv" >"$tmp/summary.txt" 2>"$tmp/class.err"
st=$?
[ "$st" -eq 1 ] || fail "the class: exit $st, expected 1 (an unknown sheet)"
python3 "$tools/item_analysis.py" "$tmp/class.json" || fail "item analysis against the reference"
# the summary with its rows (no report file given)
"$EPURE" grade --key "$tmp/set/key.json" --answers "$tmp/class2.csv" >>"$tmp/summary.txt" 2>/dev/null

# the summary and the reports: French words, no internal code
python3 - "$tmp/summary.txt" "$tmp/report.csv" "$tmp/cr/class-report.html" "$EPURE" <<'PY' || fail "French words, no codes"
import json, re, subprocess, sys
summary = open(sys.argv[1], encoding="utf-8").read()
report = open(sys.argv[2], encoding="utf-8-sig").read()
html = open(sys.argv[3], encoding="utf-8").read()
kinds = json.loads(subprocess.run([sys.argv[4], "kinds", "--json"], capture_output=True, text=True).stdout)
codes = {m for k in kinds for m in k["mistakes"]} | {"not_asked", "unknown_sheet", "to_check", "swapped_cells",
         "duplicate", "ragged", "malformed", "no_sheet", "follow_through", "unanswered", "swapped_coordinates"}
for name, text in (("summary", summary), ("report", report), ("class report", html)):
    for code in codes:
        for pattern in (f"[{code}]", f"({code})", f" {code} ", f";{code}"):
            assert pattern not in text, (name, pattern)
assert "[feuille inconnue]" in summary and "[réponses non demandées]" in summary, summary[-3000:]
assert "cohérence interne : α de Cronbach = " in summary.replace("\u00a0", " ")
assert "notes sur 20" in summary
assert "facilité" in summary and "discrimination" in summary
head = report.splitlines()[0].split(";")
assert head[:4] == ["feuille", "étudiant", "points", "max"] and "note/20" in head and head[-1] == "remarques", head
PY

# the issue's own codes: an export whose students make the mistakes norm_not_rooted and
# cross_sign, summarised in French: the mistakes' names, never their codes
"$EPURE" grade --key "$EPURE_SOURCE_DIR/tests/grading/data/key_small.json" --answers "$EPURE_SOURCE_DIR/tests/grading/data/export_fr.csv" \
  --lang fr >"$tmp/fr_summary.txt" 2>/dev/null
grep -q "‖u‖ sans la racine carrée" "$tmp/fr_summary.txt" || fail "French summary: norm_not_rooted not named"
grep -q "signe d’un produit vectoriel" "$tmp/fr_summary.txt" || fail "French summary: cross_sign not named"
grep -qE "\((norm_not_rooted|cross_sign)\)|norm_not_rooted|cross_sign" "$tmp/fr_summary.txt" && fail "French summary prints a mistake code"

# the class report: the HTML parses, the PDF is sound, the plots are there
if command -v xmllint >/dev/null; then
  xmllint --html --noout "$tmp/cr/class-report.html" 2>"$tmp/xmllint.err" || fail "class-report.html: $(head -3 "$tmp/xmllint.err")"
fi
n_svg=$(grep -o "<svg" "$tmp/cr/class-report.html" | wc -l)
[ "$n_svg" -ge 8 ] || fail "class-report.html: $n_svg plots, expected 8 or more"
if command -v qpdf >/dev/null; then
  qpdf --check "$tmp/cr/class-report.pdf" >/dev/null 2>&1 || fail "class-report.pdf: qpdf --check"
fi
if command -v pdftotext >/dev/null; then
  pdftotext "$tmp/cr/class-report.pdf" "$tmp/cr.txt"
  for words in "Les 10 notes sur 20" "facilité" "discrimination (r item–reste)" "facilité par cas" \
               "Comment ces chiffres sont calculés" "α de Cronbach"; do
    grep -q "$words" "$tmp/cr.txt" || fail "class-report.pdf does not say '$words'"
  done
fi
if command -v pdftoppm >/dev/null; then
  pdftoppm -png -r 40 -f 1 -l 1 "$tmp/cr/class-report.pdf" "$tmp/page" && [ -s "$tmp/page-1.png" ] || fail "class-report.pdf does not render"
fi

# the gradebook: the roster's students with a marked sheet, ID number first, decimal points
python3 - "$tmp/moodle.csv" "$tmp/class.json" <<'PY' || fail "the Moodle gradebook"
import csv, json, sys
rows = list(csv.reader(open(sys.argv[1], encoding="utf-8")))
assert rows[0][:3] == ["Numéro d’identification", "Adresse de courriel", "Nom complet"] and rows[0][3].endswith("(/20)"), rows[0]
marks = {s["student"]: s["mark"] for s in json.load(open(sys.argv[2], encoding="utf-8"))["submissions"] if s["marked"]}
assert len(rows) == 11, len(rows)   # 10 students; the absent one and the unknown sheet left out
for r in rows[1:]:
    assert r[0].startswith("2180") and r[1].endswith("@univ.fr"), r
    assert float(r[3]) == marks["Étudiant " + r[2].split()[0]], (r, marks)
PY
grep -q "absents" "$tmp/class.err" || fail "the absent student is not said: $(cat "$tmp/class.err")"

exit $failed
