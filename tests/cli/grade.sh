#!/usr/bin/env bash
# `epure grade` end to end on a realistic spreadsheet export (tests/grading/data/export_fr.csv:
# a French export with a BOM, CRLF, semicolons, decimal commas, quoted accented names with
# commas and quotes, exact forms, faces "-y;+x", oui/non, "avant A") against a committed key
# (key_small.json, four sheets of seed 5 cut to five exercises). Four students: one all right,
# one making a named mistake in every exercise, one with an inward normal and blanks, one with
# a norm left squared. Checks: every named mistake and follow-through seen where it was made,
# totals, follow-through off, the report in the export's own dialect, JSON answers equal to
# CSV ones, feedback sheets that parse and render. key_small.json was written under draw version
# 1: it is graded by its own content, with one warning, and its ids are not rebuilt from the
# spec (this epure draws other sheets for them). Then a set of this epure's draw, answered in
# columns named by place as older sets were: keys rebuilt from the spec (--spec builtin, --spec
# FILE) mark as its key.json does, and the feedback draws a student's far point and inward normal
# on the key's diagrams.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$EPURE_SOURCE_DIR/tests/grading/data"
failed=0
fail() { echo "FAIL: $*"; failed=1; }

"$EPURE" grade --key "$data/key_small.json" --answers "$data/export_fr.csv" --report "$tmp/report.csv" \
  --json "$tmp/marks.json" --feedback "$tmp/fb" --histogram "$tmp/hist.svg" --lang fr -q >"$tmp/out" 2>"$tmp/err"
st=$?
[ "$st" -eq 0 ] || fail "realistic export: exit $st, expected 0 ($(cat "$tmp/err"))"
# one line: the key is of an earlier draw, marked by its own values, its sheets not redrawn
[ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q "version de tirage 1).*version de tirage 2).*ne peuvent pas être redessinées" "$tmp/err" ||
  fail "realistic export: expected the one warning of an earlier draw version, got: $(cat "$tmp/err")"

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

# key_small.json's ids are of draw version 1: not rebuilt from the spec, each said with why
"$EPURE" grade --spec builtin --answers "$data/export_fr.csv" --json "$tmp/spec_v1.json" -q >/dev/null 2>"$tmp/spec_v1.err"
st=$?
[ "$st" -eq 2 ] || fail "--spec builtin on version-1 ids: exit $st, expected 2"
[ "$(grep -c "drawn by generator version 1; this epure draws version 2" "$tmp/spec_v1.err")" -eq 4 ] ||
  fail "--spec builtin on version-1 ids: not every id refused with why: $(cat "$tmp/spec_v1.err")"

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
grep -q "lointaine J" "$tmp/fb/1000-0005-0089.svg" || fail "the far intersection is not explained"
grep -q "(vous)" "$tmp"/fb/*.svg && fail "a diagram drawn from a key of another draw version"
ls "$tmp/fb" | grep -q '\.tmp$' && fail "a temporary file was left behind"

# without a report: a readable summary on stdout
"$EPURE" grade --key "$data/key_small.json" --answers "$data/export_fr.csv" >"$tmp/summary" 2>/dev/null
grep -q "N'Diaye, Aïssatou" "$tmp/summary" || fail "summary lacks a student"
grep -q "far intersection J" "$tmp/summary" || fail "summary lacks the mistakes (by name)"
grep -q "far_intersection" "$tmp/summary" && fail "summary shows a mistake code"
grep -q "median" "$tmp/summary" || fail "summary lacks the class statistics"

# A set of this epure's draw (seed 5, four French sheets), answered right but for two students:
# on the first sheet whose ray meets the circle from outside, the far point (t = t_proj + √(r² −
# d²)); on the next such sheet, the inward normal. The columns are named by place (1.dot, 4.t),
# as sets were numbered before the course named its exercises P, 1, 2, …
"$EPURE" generate --lang fr --sheets 4 --seed 5 --format svg --out "$tmp/v2" -q >/dev/null 2>"$tmp/v2.err" ||
  fail "generate: $(cat "$tmp/v2.err")"
python3 - "$tmp/v2/key.json" "$tmp/v2.csv" >"$tmp/v2.env" <<'PY' || fail "building the answers of the version-2 set"
import csv, json, math, sys
key = json.load(open(sys.argv[1], encoding="utf-8"))
numbers = [e["number"] for e in key["sheets"][0]["exercises"]]
def by_place(i):  # "P.dot" -> "1.dot", "1.t" -> "2.t", "3.3.t" -> "6.t"
    n = max((n for n in numbers if i.startswith(n + ".")), key=len)
    return f"{numbers.index(n) + 1}{i[len(n):]}"
def typed(e):
    if isinstance(e, bool): return "oui" if e else "non"
    if isinstance(e, list): return " ".join(e) if e else "aucun"
    if isinstance(e, str): return e
    return f"{round(e, 2):.2f}".replace(".", ",")
hits = [(s, e) for s in key["sheets"] for e in s["exercises"] if e["kind"] == "ray_circle" and e["branch"] == "hit"]
assert len(hits) >= 2, [(s["id"], e["branch"]) for s in key["sheets"] for e in s["exercises"] if e["kind"] == "ray_circle"]
rows, header = [], []
for s in key["sheets"]:
    cells = {by_place(q["id"]): typed(q["expected"]) for e in s["exercises"] for q in e["questions"]}
    for e in s["exercises"]:
        n = e["number"]
        if (s, e) == hits[0]:  # the far intersection, and the point on it
            x, sol = e["instance"], e["solution"]
            norm = math.hypot(*x["u"])
            t = sol["t_proj"] + math.sqrt(x["r"] ** 2 - sol["d2"])
            I = [x["A"][k] + t * x["u"][k] / norm for k in range(2)]
            for f, v in (("t", t), ("I.x", I[0]), ("I.y", I[1])): cells[by_place(f"{n}.{f}")] = typed(v)
            print(f"FAR={s['id']} FAR_T={n}.t")
        if (s, e) == hits[1]:  # the inward normal
            for f in ("N.x", "N.y"): cells[by_place(f"{n}.{f}")] = typed(-e["solution"]["N"]["xy".index(f[-1])])
            print(f"INWARD={s['id']} INWARD_N={n}.N.x")
    for c in cells:
        if c not in header: header.append(c)
    rows.append((s["id"], cells))
with open(sys.argv[2], "w", encoding="utf-8-sig", newline="") as f:
    w = csv.writer(f, delimiter=";", lineterminator="\r\n")
    w.writerow(["Feuille", "Étudiant"] + header)
    for i, (id, cells) in enumerate(rows):
        w.writerow([id, f"Étudiant {i + 1}"] + [cells.get(c, "") for c in header])
PY
. "$tmp/v2.env"
"$EPURE" grade --key "$tmp/v2/key.json" --answers "$tmp/v2.csv" --json "$tmp/v2_key.json" --feedback "$tmp/fb2" -q   >/dev/null 2>"$tmp/v2_key.err" || fail "version-2 set, --key: exit $? ($(cat "$tmp/v2_key.err"))"
python3 - "$tmp/v2_key.json" "$FAR" "$FAR_T" "$INWARD" "$INWARD_N" <<'PY' || fail "version-2 set: the two mistakes"
import json, sys
marks, far, far_t, inward, inward_n = json.load(open(sys.argv[1])), *sys.argv[2:]
by = {s["sheet"]: {q["id"]: q for q in s["questions"]} for s in marks["submissions"]}
assert by[far][far_t]["mistake"] == "far_intersection", by[far][far_t]
assert by[inward][inward_n]["mistake"] == "normal_inward", by[inward][inward_n]
for id, qs in by.items():
    wrong = [q for q in qs.values() if q["verdict"] not in ("right", "follow_through")]
    assert id in (far, inward) or not wrong, (id, wrong)
PY
grep -q "I (vous)" "$tmp/fb2/$FAR.svg" || fail "the far point is not drawn on the key diagram"
grep -q "lointaine J" "$tmp/fb2/$FAR.svg" || fail "the far intersection is not explained"
grep -q "N (vous)" "$tmp/fb2/$INWARD.svg" || fail "the inward normal is not drawn on the key diagram"

# keys rebuilt from the spec and the ids mark as key.json does, every question under its id; the
# columns named by place are read with a warning
"$EPURE" grade --spec builtin --answers "$tmp/v2.csv" --json "$tmp/spec.json" -q >/dev/null 2>"$tmp/spec.err" \
  || fail "--spec builtin: exit $? ($(cat "$tmp/spec.err"))"
grep -q "by their exercise's place" "$tmp/spec.err" || fail "--spec builtin: no warning that the columns are read by place"
"$EPURE" grade --spec "$EPURE_SOURCE_DIR/templates/course.toml" --answers "$tmp/v2.csv" --json "$tmp/spec_file.json" -q \
  >/dev/null 2>"$tmp/spec_file.err" || fail "--spec FILE: exit $? ($(cat "$tmp/spec_file.err"))"
python3 - "$tmp/v2_key.json" "$tmp/spec.json" "$tmp/spec_file.json" <<'PY' || fail "--spec marks differ from key.json's"
import json, sys
a, b, c = (json.load(open(p)) for p in sys.argv[1:])
assert len(a["submissions"]) == 4
for x, y, z in zip(a["submissions"], b["submissions"], c["submissions"]):
    assert x["sheet"] == y["sheet"] == z["sheet"]
    qa, qb, qc = ({q["id"]: (q["verdict"], q["points"], q.get("mistake")) for q in s["questions"]} for s in (x, y, z))
    assert qa == qb == qc, (x["sheet"], {k: (qa[k], qb.get(k)) for k in qa if qa[k] != qb.get(k)})
PY

[ "$failed" -eq 0 ] && echo "grade: all checks passed"
exit "$failed"
