#!/usr/bin/env bash
# `epure grade` end to end on a French class as a teacher's spreadsheet exports it: a set of ten
# French sheets is generated (the course's spec with `scale = 20`), and from its key.json a
# realistic export is written the way a French spreadsheet saves "CSV UTF-8" (BOM, CRLF, ';',
# decimal commas, accented names with commas, French column names), with the answers as
# students type them: exact forms (5-sqrt(11)), angles with their unit (50,91°, −71,57 °,
# degrés), the true minus sign, the sheet's own words for a choice (passe à côté, à l’extérieur,
# in capitals or without accents), "aucun" for no side, blanks, a point's coordinates typed
# swapped, a mistyped sheet id, an answer to a question the sheet does not ask.
# Checks: right answers earn full marks, the swap is named, units are read, every sheet is
# worth the same (exercise by exercise), marks out of 20, statistics in percent, and everything
# the teacher and the students read is French.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

# the course's spec, marked out of 20
python3 - "$EPURE_SOURCE_DIR/templates/course.toml" "$tmp/course20.toml" <<'PY'
import sys
text = open(sys.argv[1], encoding="utf-8").read()
assert "\nfollow_through = true" in text
text = text.replace("\nfollow_through = true", "\nscale = 20\nfollow_through = true", 1)
open(sys.argv[2], "w", encoding="utf-8").write(text)
PY
"$EPURE" generate --spec "$tmp/course20.toml" --lang fr --sheets 10 --seed 4242 --format svg --out "$tmp/set" -q \
  >/dev/null 2>"$tmp/gen.err" || fail "generate: $(cat "$tmp/gen.err")"

# the export, built from the key
python3 - "$tmp/set/key.json" "$EPURE_SOURCE_DIR/templates/text/fr/common.toml" "$tmp/export.csv" "$tmp/plan.json" <<'PY' || fail "building the export"
import csv, json, sys, tomllib
key = json.load(open(sys.argv[1], encoding="utf-8"))
choice = tomllib.load(open(sys.argv[2], "rb"))["choice"]
sheets = key["sheets"]
assert len(sheets) == 10, len(sheets)
assert key["spec"]["language"] == "fr" and key["spec"].get("scale") == 20, key["spec"]

names = ["Lefèvre, Zoé", "Martin, Léo", "N'Diaye, Aïssatou", "Dubois, Chloé", "Nguyễn, Thảo",
         "Girard, Élodie", "Moreau, Théo", "Lemaître, Inès", "Faure, Noé", "Roux, Maëlle"]
ids = []
for s in sheets:
    for e in s["exercises"]:
        for q in e["questions"]:
            if q["id"] not in ids: ids.append(q["id"])

def number(x, style):
    s = f"{x:.2f}"
    if s in ("-0.00",): s = "0.00"
    s = s.replace(".", ",")
    if style % 3 == 1 and s.startswith("-"): s = "\u2212" + s[1:]  # a true minus sign
    return s

def cell(q, field, style):
    x = q["expected"]
    if isinstance(x, bool):
        return ["oui", "Oui", "OUI", "vrai"][style % 4] if x else ["non", "Non", "NON", "faux"][style % 4]
    if isinstance(x, str):
        if x == "miss": return ["passe à côté", "Passe a cote", "manqué", "MANQUE"][style % 4]
        if x == "outside": return ["à l'extérieur", "A L’EXTERIEUR", "à l’extérieur", "exterieur"][style % 4]
        words = choice[x]
        return [words, words.upper(), words.replace("è", "e").replace("é", "e").replace("à", "a")][style % 3]
    if isinstance(x, list):
        if not x: return ["aucun", "Aucun", "aucune", "rien"][style % 4]
        return ";".join(x) if style % 2 == 0 else " ".join(reversed(x))
    if field == "angle_deg":
        return number(x, style) + ["°", " °", " degrés", "°"][style % 4]
    if q.get("exact") and "sqrt" in q["exact"] and style % 2 == 0:
        return q["exact"]  # the key's exact form, as a student may type it: 5-sqrt(11)
    return number(x, style)

plan = {"swapped": [], "blank": [], "not_asked": None, "mistyped": None, "angles": []}
rows = []
for i, s in enumerate(sheets):
    answers = {}
    for e in s["exercises"]:
        for q in e["questions"]:
            field = q["id"].split(".", 1)[1]
            answers[q["id"]] = cell(q, field, i + len(answers))
            if field == "angle_deg": plan["angles"].append((i, q["id"], answers[q["id"]]))
    sheet_id = s["id"]
    if i == 1:
        # x and y typed the wrong way round, in a point whose coordinates differ
        qs = {q["id"]: q for e in s["exercises"] for q in e["questions"]}
        for qid, q in qs.items():
            if not qid.endswith(".x") or not q.get("point"): continue
            y = qid[:-1] + "y"
            if y not in qs or abs(q["expected"] - qs[y]["expected"]) < 0.5: continue
            answers[qid], answers[y] = answers[y], answers[qid]
            plan["swapped"] += [qid, y]
            break
        assert plan["swapped"], "no point to swap"
    if i == 2:
        # one character mistyped: the check character catches it
        chars = list(sheet_id)
        k = 6
        chars[k] = "7" if chars[k] != "7" else "8"
        sheet_id = "".join(chars)
        plan["mistyped"] = {"row": i, "typed": sheet_id, "meant": s["id"]}
    if i == 3:
        for qid in list(answers)[2:4]:
            answers[qid] = ""
            plan["blank"].append(qid)
    if i == 4:
        stray = next(q for q in ids if q not in answers)
        answers[stray] = "1,5"
        plan["not_asked"] = {"row": i, "id": stray}
    rows.append([sheet_id, names[i]] + [answers.get(q, "") for q in ids])

with open(sys.argv[3], "w", encoding="utf-8-sig", newline="") as f:
    w = csv.writer(f, delimiter=";", lineterminator="\r\n")
    w.writerow(["Feuille", "Étudiant"] + ids)
    w.writerows(rows)
json.dump(plan, open(sys.argv[4], "w"), ensure_ascii=False)
PY

"$EPURE" grade --key "$tmp/set/key.json" --answers "$tmp/export.csv" --report "$tmp/marks.csv" --json "$tmp/marks.json" \
  --feedback "$tmp/fb" >"$tmp/out" 2>"$tmp/err"
st=$?
# the mistyped id and the answer to a question not asked are errors: said, and the rest marked
[ "$st" -eq 1 ] || fail "exit $st, expected 1 ($(cat "$tmp/err"))"
"$EPURE" grade --key "$tmp/set/key.json" --answers "$tmp/export.csv" >"$tmp/summary" 2>/dev/null

python3 - "$tmp" <<'PY' || fail "marks of the French export"
import csv, glob, html, io, json, re, sys
tmp = sys.argv[1]
marks = json.load(open(f"{tmp}/marks.json", encoding="utf-8"))
plan = json.load(open(f"{tmp}/plan.json", encoding="utf-8"))
subs = marks["submissions"]
assert len(subs) == 10, len(subs)
assert marks["language"] == "fr"

# every sheet is worth the same in all; exercise 1 (the projection, `points = 5` in the spec)
# the same on every sheet; the others share the rest by the work of the case each sheet drew
# (work-fair sheets), so the same case earns about the same everywhere (the sheets' work is
# within 10 % of the set's mean: tests/exercises/sheet_points_test.cpp)
key = json.load(open(f"{tmp}/set/key.json", encoding="utf-8"))
branch_of = {(sh["id"], e["number"]): e["branch"] for sh in key["sheets"] for e in sh["exercises"]}
numbers = sorted({e["number"] for sh in key["sheets"] for e in sh["exercises"]}, key=len, reverse=True)
def exercise(qid):  # "3.3.t" is exercise 3.3's, "3.t" exercise 3's
    return next(n for n in numbers if qid.startswith(n + "."))
marked = [s for s in subs if s["marked"]]
assert len(marked) == 9, [s["student"] for s in subs if not s["marked"]]
by_case = {}
for s in marked:
    ex = {}
    for x in s["questions"]:
        n = exercise(x["id"])
        ex[n] = ex.get(n, 0) + x["max_points"]
    assert all(abs(x["max_points"] * 4 - round(x["max_points"] * 4)) < 1e-9 for x in s["questions"]), s["student"]
    assert abs(ex["1"] - 5) < 1e-9, (s["student"], ex["1"])
    for n, p in ex.items():
        by_case.setdefault((n, branch_of[(s["sheet"], n)]), []).append(p)
assert len({s["max"] for s in marked}) == 1, {s["max"] for s in marked}
for case, points in by_case.items():
    assert max(points) <= 1.25 * min(points), (case, points)
# marks out of 20
for s in marked:
    assert abs(s["mark"] - round(s["score"] / s["max"] * 20, 2)) < 1e-9, (s["score"], s["max"], s["mark"])

by_row = {i + 2: s for i, s in enumerate(subs)}  # line 1 is the header
special = {plan["mistyped"]["row"], 1, 3}
for i in range(10):
    s = by_row[i + 2]
    if i in special: continue
    wrong = [(x["id"], x["given"], x["verdict"]) for x in s["questions"] if x["verdict"] != "right"]
    assert not wrong and s["score"] == s["max"], (s["student"], wrong)

# the units of the angles were read
for row, qid, typed in plan["angles"]:
    if row in special: continue
    x = next(x for x in by_row[row + 2]["questions"] if x["id"] == qid)
    assert x["verdict"] == "right", (typed, x)

# the swapped coordinates are named, the rest of that sheet is right
q = {x["id"]: x for x in by_row[3]["questions"]}
for qid in plan["swapped"]:
    assert q[qid]["verdict"] == "wrong" and q[qid]["mistake"] == "swapped_coordinates", q[qid]
    assert "inversé x et y" in q[qid]["feedback"], q[qid]["feedback"]
others = [x for x in by_row[3]["questions"] if x["id"] not in plan["swapped"] and x["verdict"] != "right"]
assert all(x["verdict"] == "follow_through" for x in others), others

# blanks are "sans réponse", and only they lose points
q = {x["id"]: x for x in by_row[5]["questions"]}
for qid in plan["blank"]:
    assert q[qid]["verdict"] == "unanswered" and q[qid]["feedback"].startswith("Sans réponse"), q[qid]

# the mistyped id: not marked, said in French, the meant sheet suggested
m = by_row[plan["mistyped"]["row"] + 2]
assert not m["marked"] and [f["code"] for f in m["flags"]] == ["unknown_sheet"], m["flags"]
msg = m["flags"][0]["message"]
assert "n’est pas un identifiant de feuille valide" in msg and "caractère de contrôle" in msg, msg
assert plan["mistyped"]["meant"] in msg and "la plus proche" in msg, msg

# the answer to a question the sheet does not ask: flagged in French, not marked
s = by_row[plan["not_asked"]["row"] + 2]
flags = {f["code"]: f["message"] for f in s["flags"]}
assert "not_asked" in flags and "ne pose pas" in flags["not_asked"] and plan["not_asked"]["id"] in flags["not_asked"], flags
assert s["score"] == s["max"], s["score"]

# statistics in percent of the maximum
st = marks["statistics"]
assert abs(st["mean_percent"] - sum(100 * s["score"] / s["max"] for s in marked) / 9) < 1e-9, st["mean_percent"]
assert st["scale"] == 20 and abs(st["mean_mark"] - st["mean_percent"] / 5) < 1e-9

# the report: the export's dialect, with the mark out of 20
raw = open(f"{tmp}/marks.csv", "rb").read()
assert raw.startswith(b"\xef\xbb\xbf") and b"\r\n" in raw
rows = list(csv.reader(io.StringIO(raw.decode("utf-8-sig")), delimiter=";"))
assert rows[0][:6] == ["feuille", "étudiant", "points", "max", "note/20", "à vérifier"], rows[0][:6]
for r, s in zip(rows[1:], subs):
    if s["marked"]: assert abs(float(r[4].replace(",", ".")) - s["mark"]) < 1e-9, (r[4], s["mark"])

# French only: what the students and the teacher read
english = ["Expected", "you gave", "not answered", "Not answered", "does not ask", "not a valid sheet id",
           "check character", "nearest sheet", "Right from", "your own", "Score", "unreadable", "follow-through",
           "marked sheet", "rows read", "success rate", "most frequent", "warning", "error:", "outside", "between",
           "before A", "after B", "miss", "behind", "parallel", "collinear", "none", "yes", "Your ",
           "not_asked", "unknown_sheet", "swapped_coordinates", "to_check", "duplicate", "held", "to check"]
def english_in(text):
    return [w for w in english if re.search(r"(?<!\w)" + re.escape(w) + r"(?!\w)", text)]
texts = {"stdout": open(f"{tmp}/summary", encoding="utf-8").read(), "stderr": open(f"{tmp}/err", encoding="utf-8").read()}
for s in subs:
    for f in s["flags"]: texts[f"flag {s['line']} {f['code']}"] = f["message"]
    for x in s["questions"]: texts[f"feedback {x['id']} line {s['line']}"] = x["feedback"]
for p in marks["problems"]: texts[f"problem {p['line']}"] = p["message"]
for path in sorted(glob.glob(f"{tmp}/fb/*.svg")):
    svg = open(path, encoding="utf-8").read()
    svg = re.sub(r"<style.*?</style>|<defs.*?</defs>|<desc.*?</desc>", " ", svg, flags=re.S)
    texts[path] = html.unescape(re.sub(r"<[^>]+>", " ", svg))
bad = {where: english_in(t) for where, t in texts.items() if english_in(t)}
assert not bad, bad
assert "facilité (part de la classe qui l’a réussie)" in texts["stdout"] and "%" in texts["stdout"], texts["stdout"]
assert "α de Cronbach" in texts["stdout"], texts["stdout"]
assert "sur 20" in texts["stdout"], texts["stdout"]
# the sheet's words for a choice on the feedback sheets: "✓ à l’extérieur", never the word typed
fb = " ".join(t for w, t in texts.items() if w.endswith(".svg"))
assert "✓ passe à côté" not in fb and "✓ Passe a cote" not in fb and "✓ A L’EXTERIEUR" not in fb, \
    "a choice shown as typed, not in the sheet's words"
assert "✓ manqué" in fb or "✓ à l’extérieur" in fb, "no choice shown in the sheet's words"
PY

# determinism: the same export marks to the same bytes
"$EPURE" grade --key "$tmp/set/key.json" --answers "$tmp/export.csv" --report "$tmp/marks2.csv" --json "$tmp/marks2.json" \
  -q >/dev/null 2>&1
cmp -s "$tmp/marks.csv" "$tmp/marks2.csv" || fail "report differs between two runs"
cmp -s "$tmp/marks.json" "$tmp/marks2.json" || fail "JSON differs between two runs"

exit $failed
