#!/usr/bin/env bash
# `epure grade` end to end on a realistic spreadsheet export (tests/grading/data/export_fr.csv:
# a French export with a BOM, CRLF, semicolons, decimal commas, quoted accented names with
# commas and quotes, exact forms, faces "-y;+x", oui/non, "avant A") against a committed key
# (key_small.json, four sheets of seed 5 cut to five exercises). Four students: one all right,
# one making a named mistake in every exercise, one with an inward normal and blanks, one with
# a norm left squared. Checks: every named mistake and follow-through seen where it was made,
# totals, follow-through off, the report in the export's own dialect, JSON answers equal to
# CSV ones, keys rebuilt from the spec (--spec builtin), feedback sheets that parse and render.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$EPURE_SOURCE_DIR/tests/grading/data"
failed=0
fail() { echo "FAIL: $*"; failed=1; }

"$EPURE" grade --key "$data/key_small.json" --answers "$data/export_fr.csv" --report "$tmp/report.csv" \
  --json "$tmp/marks.json" --feedback "$tmp/fb" --histogram "$tmp/hist.svg" --lang fr -q >"$tmp/out" 2>"$tmp/err"
st=$?
[ "$st" -eq 0 ] || fail "realistic export: exit $st, expected 0 ($(cat "$tmp/err"))"
[ -s "$tmp/err" ] && fail "realistic export: unexpected problems: $(cat "$tmp/err")"

python3 - "$tmp/marks.json" "$tmp/report.csv" <<'PY' || fail "marks of the realistic export"
import json, sys, csv, io
marks = json.load(open(sys.argv[1]))
subs = marks["submissions"]
assert [s["line"] for s in subs] == [2, 3, 4, 5], [s["line"] for s in subs]
by = {s["student"]: s for s in subs}
assert set(by) == {"Lefèvre, Zoé", "N'Diaye, Aïssatou", 'O\'Brien, Seán "Shane"', "Müller, Jörg"}, set(by)
for s in subs:
    q = s["questions"]
    assert abs(sum(x["points"] for x in q) - s["score"]) < 1e-9, s["student"]
    assert abs(sum(x["max_points"] for x in q) - s["max"]) < 1e-9, s["student"]
    assert {"line", "sheet", "student", "marked", "score", "max", "flags", "questions"} <= set(s), set(s)
    for x in q:
        assert {"id", "expected", "given", "verdict", "points", "max_points", "feedback", "mistake"} <= set(x), set(x)
        assert x["verdict"] in ("right", "follow_through", "wrong", "unanswered", "unreadable"), x
        if x["verdict"] == "right":
            assert x["feedback"] == "" and x["points"] == x["max_points"], x
        else:
            assert x["feedback"], x
zoe = by["Lefèvre, Zoé"]
assert zoe["score"] == zoe["max"], zoe["score"]  # exact forms, decimal commas, faces "-y;+x"
q = {x["id"]: x for x in by["N'Diaye, Aïssatou"]["questions"]}
expect = {
    "1.cross": ("wrong", "cross_sign"), "1.sin": ("follow_through", None), "1.angle_deg": ("follow_through", None),
    "2.t": ("wrong", "t_unsquared_norm"), "2.P.x": ("follow_through", None), "2.P.y": ("follow_through", None),
    "2.position": ("follow_through", None),
    "3.t_ab": ("wrong", "t_swapped"), "3.t_cd": ("wrong", "t_swapped"),
    "4.t": ("wrong", "far_intersection"), "4.I.x": ("follow_through", None), "4.I.y": ("follow_through", None),
    "4.N.x": ("follow_through", None), "4.N.y": ("follow_through", None),
    "5.faces": ("wrong", "faces_wrong_half_planes"),
}
for id, (verdict, code) in expect.items():
    assert q[id]["verdict"] == verdict, (id, q[id])
    assert q[id]["mistake"] == code, (id, q[id])
assert q["2.P.x"]["from"] == "t" and q["2.P.x"]["from_answers"] == "t = 2,77", q["2.P.x"]
assert "report d’erreur" in q["2.P.x"]["feedback"], q["2.P.x"]["feedback"]  # French sentences
assert "‖AB‖²" in q["2.t"]["feedback"], q["2.t"]["feedback"]
q = {x["id"]: x for x in by['O\'Brien, Seán "Shane"']["questions"]}
assert q["4.N.x"]["mistake"] == "normal_inward" and q["4.N.y"]["mistake"] == "normal_inward", q["4.N.x"]
assert q["5.N.x"]["verdict"] == "unanswered" and q["5.N.x"]["given"] is None
q = {x["id"]: x for x in by["Müller, Jörg"]["questions"]}
assert q["1.norm_u"]["mistake"] == "norm_not_rooted" and q["1.cos"]["verdict"] == "follow_through"
st = marks["statistics"]
assert st["rows"] == 4 and st["marked"] == 4
assert {"mean", "median", "min", "max", "questions", "mistakes", "histogram"} <= set(st), set(st)
scores = sorted(s["score"] for s in subs)
rate = {x["id"]: x["success_rate"] for x in st["questions"]}
assert rate["1.cross"] == 0.75 and rate["1.dot"] == 1, rate
assert abs(st["mean"] - sum(scores) / 4) < 1e-9 and abs(st["median"] - (scores[1] + scores[2]) / 2) < 1e-9, st
codes = {(m["code"], m["question"]) for m in st["mistakes"]}
assert ("far_intersection", "4.t") in codes and ("t_unsquared_norm", "2.t") in codes, codes
assert marks["exit_status"] == 0 and marks["errors"] == 0

# the report: the export's dialect (BOM, ';', decimal comma, CRLF), one row per submission
raw = open(sys.argv[2], "rb").read()
assert raw.startswith(b"\xef\xbb\xbf"), "report without the export's BOM"
assert b"\r\n" in raw, "report without the export's CRLF"
rows = list(csv.reader(io.StringIO(raw.decode("utf-8-sig")), delimiter=";"))
# the header in the feedback's language (--lang fr); an English set: points, no mark out of 20
assert rows[0][:5] == ["feuille", "étudiant", "points", "max", "à vérifier"], rows[0][:5]
assert rows[0][-2:] == ["ligne", "remarques"], rows[0][-2:]
assert len(rows) == 5, len(rows)
ids = rows[0][5:-2]
for r, s in zip(rows[1:], subs):
    assert r[1] == s["student"], (r[1], s["student"])
    assert float(r[2].replace(",", ".")) == s["score"], (r[2], s["score"])
    points = {x["id"]: x["points"] for x in s["questions"]}
    for id, cell in zip(ids, r[5:-2]):
        if id in points: assert float(cell.replace(",", ".")) == points[id], (id, cell)
        else: assert cell == "", (id, cell)
PY

# follow-through off: the same marks minus exactly the follow-through credit
"$EPURE" grade --key "$data/key_small.json" --answers "$data/export_fr.csv" --json "$tmp/off.json" --no-follow-through -q \
  >/dev/null 2>&1 || fail "--no-follow-through: exit $?"
python3 - "$tmp/marks.json" "$tmp/off.json" <<'PY' || fail "follow-through off"
import json, sys
on, off = (json.load(open(p)) for p in sys.argv[1:])
assert on["follow_through"] is True and off["follow_through"] is False
for a, b in zip(on["submissions"], off["submissions"]):
    ft = sum(x["points"] for x in a["questions"] if x["verdict"] == "follow_through")
    assert abs(a["score"] - ft - b["score"]) < 1e-9, (a["student"], a["score"], ft, b["score"])
    for x, y in zip(a["questions"], b["questions"]):
        if x["verdict"] == "follow_through":
            assert y["verdict"] == "wrong" and y["points"] == 0 and y.get("from") == x["from"], (x, y)
            assert y["mistake"] == x["mistake"], (x, y)
n = sum(x["verdict"] == "follow_through" for s in on["submissions"] for x in s["questions"])
assert n >= 8, n
PY

# the same answers as JSON (an array, and JSON Lines) mark the same
python3 - "$data/export_fr.csv" "$tmp/answers.json" "$tmp/answers.jsonl" <<'PY'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1], encoding="utf-8-sig"), delimiter=";"))
objs = []
for r in rows:
    o = {"sheet": r.pop("Feuille"), "student": r.pop("Étudiant"), "answers": {k: v for k, v in r.items() if v}}
    objs.append(o)
json.dump(objs, open(sys.argv[2], "w"), ensure_ascii=False, indent=1)
with open(sys.argv[3], "w") as f:
    for o in objs: f.write(json.dumps(o, ensure_ascii=False) + "\n")
PY
for form in json jsonl; do
  "$EPURE" grade --key "$data/key_small.json" --answers "$tmp/answers.$form" --json "$tmp/from_$form.json" -q \
    >/dev/null 2>"$tmp/$form.err" || fail "answers as $form: exit $? ($(cat "$tmp/$form.err"))"
  python3 - "$tmp/marks.json" "$tmp/from_$form.json" <<'PY' || fail "answers as $form differ from the CSV's"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
assert [s["score"] for s in a["submissions"]] == [s["score"] for s in b["submissions"]]
assert [s["student"] for s in a["submissions"]] == [s["student"] for s in b["submissions"]]
PY
done

# keys rebuilt from the spec and the ids: the same points on every question the small key has.
# The export's header names questions by place (1.dot, 2.t), as the sheets of key_small.json
# were printed; the course's spec now numbers its exercises P, 1, 2, …: the header is read by
# place, with a warning, and every question marked as before under its new id.
"$EPURE" grade --spec builtin --answers "$data/export_fr.csv" --json "$tmp/spec.json" -q >/dev/null 2>"$tmp/spec.err" \
  || fail "--spec builtin: exit $? ($(cat "$tmp/spec.err"))"
grep -q "by their exercise's place" "$tmp/spec.err" || fail "--spec builtin: no warning that the columns are read by place"
python3 - "$tmp/marks.json" "$tmp/spec.json" <<'PY' || fail "--spec builtin marks differ from key.json's"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
numbers = ["P", "1", "2", "3", "4", "3.3", "4.3"]  # templates/course.toml
def by_place(i):  # "P.dot" -> "1.dot", "1.t" -> "2.t", "3.3.t" -> "6.t"
    n = max((n for n in numbers if i.startswith(n + ".")), key=len)
    return f"{numbers.index(n) + 1}{i[len(n):]}"
for x, y in zip(a["submissions"], b["submissions"]):
    assert x["sheet"] == y["sheet"]
    py = {by_place(q["id"]): q["points"] for q in y["questions"]}
    for q in x["questions"]:
        assert py[q["id"]] == q["points"], (x["sheet"], q["id"], q["points"], py[q["id"]])
PY

# the spec as a file (the built-in one, templates/course.toml) marks as --spec builtin does
"$EPURE" grade --spec "$EPURE_SOURCE_DIR/templates/course.toml" --answers "$data/export_fr.csv" --json "$tmp/spec_file.json" -q \
  >/dev/null 2>"$tmp/spec_file.err" || fail "--spec FILE: exit $? ($(cat "$tmp/spec_file.err"))"
python3 - "$tmp/spec.json" "$tmp/spec_file.json" <<'PY' || fail "--spec FILE marks differ from --spec builtin's"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
assert [s["score"] for s in a["submissions"]] == [s["score"] for s in b["submissions"]]
PY

# feedback sheets: one per student (SVG and PDF) and the class histogram, well-formed and renderable
[ "$(ls "$tmp/fb" | wc -l)" -eq 9 ] || fail "expected 4 feedback sheets as SVG and PDF and class.svg, got: $(ls "$tmp/fb")"
for f in "$tmp"/fb/*.pdf; do
  qpdf --check "$f" >/dev/null || fail "$(basename "$f") fails qpdf --check"
  id=$(basename "$f" .pdf)
  [ "$(pdfinfo "$f" | awk '/^Pages:/ {print $2}')" -eq "$(grep -c 'class="page"' "$tmp/fb/$id.svg")" ] ||
    fail "$id.pdf and $id.svg have different page counts"
done
pdftotext "$tmp/fb/1000-0005-0089.pdf" - | grep -q "lointaine J" || fail "the PDF feedback lacks the explanation"
for f in "$tmp"/fb/*.svg "$tmp/hist.svg"; do
  xmllint --noout "$f" 2>/dev/null || fail "$(basename "$f") is not well-formed"
  rsvg-convert -o "$tmp/render.png" "$f" 2>/dev/null || fail "$(basename "$f") does not render"
done
grep -q "N (vous)" "$tmp/fb/1000-0005-004H.svg" || fail "the inward normal is not drawn on the key diagram"
grep -q "I (vous)" "$tmp/fb/1000-0005-0089.svg" || fail "the far point is not drawn on the key diagram"
grep -q "lointaine J" "$tmp/fb/1000-0005-0089.svg" || fail "the far intersection is not explained"
ls "$tmp/fb" | grep -q '\.tmp$' && fail "a temporary file was left behind"

# without a report: a readable summary on stdout
"$EPURE" grade --key "$data/key_small.json" --answers "$data/export_fr.csv" >"$tmp/summary" 2>/dev/null
grep -q "N'Diaye, Aïssatou" "$tmp/summary" || fail "summary lacks a student"
grep -q "far intersection J" "$tmp/summary" || fail "summary lacks the mistakes (by name)"
grep -q "far_intersection" "$tmp/summary" && fail "summary shows a mistake code"
grep -q "median" "$tmp/summary" || fail "summary lacks the class statistics"

[ "$failed" -eq 0 ] && echo "grade: all checks passed"
exit "$failed"
