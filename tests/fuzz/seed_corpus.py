#!/usr/bin/env python3
"""Writes the seed corpora of tests/fuzz/corpus/<target>/ from the project's examples, goldens and
tests, and from realistic exports written out here (French Excel, LibreOffice, Google Sheets,
Moodle's response report). The crashes kept as regressions (corpus/<target>/regression-*) and
the long runs' new inputs, minimised with libFuzzer's -merge=1 (corpus/<target>/found-*), are left
as they are. Run from anywhere: python3 tests/fuzz/seed_corpus.py"""
import hashlib, json, os, re, sys

root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
corpus = os.path.join(root, "tests", "fuzz", "corpus")
shared = os.path.join(os.path.dirname(root), "shared")


def put(target, name, data):
    if isinstance(data, str):
        data = data.encode()
    d = os.path.join(corpus, target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "seed-" + name), "wb") as f:
        f.write(data)


def read(*parts):
    with open(os.path.join(*parts), "rb") as f:
        return f.read()


# solve: every example line alone, and a few lines together (one output line per input line)
lines = []
for path in ["tests/solve/examples/solve.input.jsonl", "tests/solve/adversarial.input.jsonl"]:
    lines += [l for l in read(root, path).decode().splitlines() if l.strip()]
ex = os.path.join(shared, "examples", "solve.input.jsonl")
if os.path.exists(ex):
    lines += [l for l in read(ex).decode().splitlines() if l.strip()]
seen = set()
for l in lines:
    if l in seen:
        continue
    seen.add(l)
    put("solve", hashlib.sha1(l.encode()).hexdigest()[:12], l)
put("solve", "several", "\n".join(lines[:6]) + "\n\n  \r\n" + lines[0] + "\r\n")

# key.json: the small key, each golden's first sheet as a key of its own
put("key", "key_small.json", read(root, "tests/grading/data/key_small.json"))
for g in ["seed1-en", "seed2-fr"]:
    k = json.loads(read(root, "tests/golden", g, "key.json"))
    one = dict(k, sheets=k["sheets"][:1])
    put("key", g + "-one-sheet.json", json.dumps(one, ensure_ascii=False, indent=1))
    # instances of the key are solve inputs too
    for s in k["sheets"][:1]:
        for e in s["exercises"]:
            put("solve", g + "-" + str(e["n"]), json.dumps(e["instance"]))
ids = set()
for g in ["seed1-en", "seed2-fr"]:
    ids |= {s["id"] for s in json.loads(read(root, "tests/golden", g, "key.json"))["sheets"]}

# spec: the course, and the specs of the tests
put("spec", "course.toml", read(root, "templates/course.toml"))
put("spec", "words-by-language.toml", '''title = { en = "Rays", fr = "Rayons" }
course = "Infographie"
language = "fr"
page = "letter"
decimals = 3
scale = 20
follow_through = false
difficulty = "hard"

[[exercise]]
kind = "ray_circle"
points = 4
branches = { hit = 2, miss = 1 }
questions = { t = { points = 2, abs = 0.01 } }

[[exercise]]
kind = "segments"
difficulty = "easy"
''')
spec_test = read(root, "tests/exercises/spec_test.cpp").decode()
for i, m in enumerate(re.findall(r'R"\((.*?)\)"', spec_test, re.S)):
    put("spec", "spec_test-%d.toml" % i, m)

# sheet ids: as printed, and as people type them
for i, s in enumerate(sorted(ids)[:20]):
    put("sheet_id", "golden-%d" % i, s)
if ids:
    s = sorted(ids)[0]
    put("sheet_id", "typed-lower", s.lower().replace("-", " "))
    put("sheet_id", "typed-o-for-0", s.replace("0", "O").replace("1", "l"))

# expression: what students type
for i, t in enumerate(["2.17", "2,17", "\u22120.25", "3/4", "5-sqrt(11)", "\u221a11", "2*sqrt(3)/3",
                       "(5 \u2212 2\u221a2)/3", "2\u221a3", "\u2248 2,17", "50,91\u00b0", "\u221271,57 \u00b0",
                       "50.91 deg", "50,91 degr\u00e9s", "1.5e-3", "pi/2", "racine(2)/2", "3\u00b2", "2^3",
                       "1,5\u00d72", "((((2))))", "-3*sqrt(34)/34", "180/4\u00b0", "~ 0,5", "= 1/3", "1/0",
                       "sqrt(-2)", "  4  ", "-12\u00a0\u00b0", "2 \u00f7 3", "2\u00b73", "\u03c0"]):
    put("expression", "%02d" % i, t)
# units and names typed around a number (issue 31)
for i, t in enumerate(["4,75 cm", "1,04 u", "1,8 u\u00b2", "3 unit\u00e9s", "t = 4,75", "d\u00b2 = 1,8", "I.x=2,14 cm",
                       "0.89 rad", "5 cm cm", "4,75.", "\u221a11 u"]):
    put("expression", "unit-%02d" % i, t)

# answers CSV: the French export of the tests, and realistic exports of each spreadsheet
put("answers_csv", "export_fr.csv", b"\x00" + read(root, "tests/grading/data/export_fr.csv"))
# the course's ids (templates/course.toml numbers its exercises P, 1, 2, 3, 4, 3.3, 4.3)
header = ["sheet", "student", "P.dot", "P.cross", "1.t", "1.P.x", "1.P.y", "4.faces"]
rows = [[sorted(ids)[0] if ids else "1000-0001-000X", "Lef\u00e8vre, Zo\u00e9", "0", "30", "-0,48", "9,41", "3,97", "-y;+x"],
        [sorted(ids)[1] if len(ids) > 1 else "1000-0002-000Y", "N'Diaye, A\u00efssatou", "13", "-16", "2,77", "", "", "none"]]
def csv(rows, d, q=lambda c: c, nl="\r\n"):
    return nl.join(d.join(q(c) for c in r) for r in rows) + nl
def rfc(d):
    return lambda c: '"' + c.replace('"', '""') + '"' if (d in c or '"' in c or "\n" in c) else c
# Excel (French): ';', decimal commas, CRLF, UTF-8 with a byte-order mark
put("answers_csv", "excel-fr-utf8.csv", b"\x00\xef\xbb\xbf" + csv([header] + rows, ";", rfc(";")).encode())
# Excel (French), "CSV (séparateur : point-virgule)": Windows-1252
put("answers_csv", "excel-fr-cp1252.csv", b"\x00" + csv([header] + rows, ";", rfc(";")).encode("cp1252"))
# LibreOffice: ',' with every text cell quoted, LF
put("answers_csv", "libreoffice.csv", b"\x00" + csv([header] + rows, ",", lambda c: '"%s"' % c.replace('"', '""'), "\n").encode())
# Google Sheets: ',', quotes only where needed, no line end after the last row, a timestamp column
gs = [["Timestamp"] + header] + [["2026/11/30 10:1%d:00 AM" % i] + [c.replace(",", ".") for c in r] for i, r in enumerate(rows)]
put("answers_csv", "google-sheets.csv", b"\x00" + csv(gs, ",", rfc(","), "\r\n").rstrip(b"\r\n".decode()).encode())
# a tab-separated copy and a cell with a line break inside quotes
put("answers_csv", "tabs.tsv", b"\x00" + csv([header] + rows, "\t").encode())
put("answers_csv", "multiline.csv", b"\x02" + 'sheet;student;P.dot\n1000-0001-000X;"two\nlines";"1;5"\n\n"x""y";"";3\n'.encode())
# Moodle's responses report: one row per attempt, "Response n" columns, "-" for no answer
moodle = [["Surname", "First name", "Email address", "State", "Started on", "Completed", "Time taken",
           "Grade/10.00", "Response 1", "Response 2", "Response 3"],
          ["Lef\u00e8vre", "Zo\u00e9", "zoe@example.org", "Finished", "30 November 2026  10:02 AM",
           "30 November 2026  10:31 AM", "29 mins 3 secs", "7.50", "0", "30", "-"],
          ["Overall average", "", "", "", "", "", "", "7.50", "", "", ""]]
put("answers_csv", "moodle-responses.csv", b"\x00\xef\xbb\xbf" + csv(moodle, ",", rfc(",")).encode())

# answers JSON: an array, JSON Lines, answers under "answers", points as [x, y], faces as lists
objs = [{"sheet": r[0], "student": r[1], "P.dot": 0, "1.t": "-0,48", "1.P": [9.41, 3.97], "4.faces": ["-y", "+x"]} for r in rows]
put("answers_json", "array.json", json.dumps(objs, ensure_ascii=False, indent=2))
put("answers_json", "lines.jsonl", "\n".join(json.dumps(o, ensure_ascii=False) for o in objs) + "\n\n")
put("answers_json", "nested.jsonl", "\ufeff" + json.dumps({"sheet": "1000-0001-000X", "answers": {"P.dot": 3, "P.cross": None, "3.inside": True}}) + "\r\nnot json\r\n[1,2]\n")
put("answers_json", "moodle-like.json", json.dumps([{"sheet": "1000-0001-000X", "student": "Zo\u00e9", "answers": {"1.t": "1/6", "4.faces": [], "3.3.t": "0,5"}}, 5, "x", [[[]]]]))
# the teacher's corrections: as epure scan's review page writes them, by hand, and broken ones
put("corrections", "review.json", json.dumps({"format": "epure-corrections", "version": 1, "corrections": [
    {"sheet": "1000-0005-002N", "question": "1.t", "value": "\u22120,48", "note": "a blot over the 8"},
    {"sheet": "1000-0005-002N", "question": "student_number", "value": "21804512"},
    {"sheet": "10000005002n", "question": "4.faces", "value": "+x \u2212y", "crop": "pages/3.png"}]}, ensure_ascii=False, indent=1))
put("corrections", "bom-empty.json", "\ufeff" + json.dumps({"format": "epure-corrections", "version": 1, "corrections": []}))
put("corrections", "bad-entries.json", json.dumps({"format": "epure-corrections", "version": 1, "corrections": [
    {"sheet": "A", "value": 3}, "x", {"sheet": "", "question": "1.t", "value": ""}, {"sheet": "A", "question": "1.t", "value": "1", "note": []}]}))
put("corrections", "other-version.json", '{"format": "epure-corrections", "version": 2, "corrections": []}')
put("corrections", "not-an-object.json", '[{"sheet": "A"}]')

# the class roster: a French export with its header, one without, problems
put("roster", "fr-excel.csv", "\ufeffNom;Pr\u00e9nom;N\u00b0 \u00e9tudiant;Courriel\r\nLef\u00e8vre;Zo\u00e9;00412;zoe@univ.fr\r\nMartin;L\u00e9o;21804512;leo@univ.fr\r\n")
put("roster", "no-header.csv", '21800001,"Dupont, Jean",jean@u.fr\n21800002,Marie Curie\n')
put("roster", "problems.csv", "student number,name,e-mail\n1,Ann,ann@u.edu\n1,Bob,bob@u.edu\n,Carl,c@u.edu\n4,,d@u.edu\n5,Eve,eve-at-u\n\"6\",\"Ann\n2\",a@b\n")
put("roster", "cp1252.csv", "num\u00e9ro;nom\n1;\u00c9lise\n".encode("cp1252"))
print("corpus written under", corpus)
