#!/usr/bin/env bash
# The CSV reader against Python's csv module: random cells (delimiters, quotes, line breaks,
# accents, √) written by csv.writer in every dialect a spreadsheet uses (comma, semicolon, tab;
# quoting minimal or all; CRLF or LF; with or without a BOM), graded with --json, and every
# student name and every answer epure read compared with what Python reads.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$EPURE_SOURCE_DIR/tests/grading/data"
failed=0
fail() { echo "FAIL: $*"; failed=1; }

for seed in 1 2 3 4 5 6 7 8 9 10 11 12; do
  python3 - "$seed" "$tmp/answers.csv" "$tmp/expected.json" <<'PY'
import csv, json, random, sys
seed = int(sys.argv[1])
rng = random.Random(seed)
delimiter = [",", ";", "\t"][seed % 3]
quoting = csv.QUOTE_ALL if seed % 2 else csv.QUOTE_MINIMAL
newline = "\r\n" if seed % 4 < 2 else "\n"
bom = seed % 5 == 0
sheets = ["1000-0005-002N", "1000-0005-0089", "1000-0005-004H", "1000-0005-003K"]
columns = ["2.t", "2.position", "1.dot", "3.intersects"]
pieces = ["a", "Z", "0", "7", ",", ";", "\t", '"', " ", "\n", "\r\n", "é", "√", "-", ".", "oui", "'"]
def cell():
    s = "".join(rng.choice(pieces) for _ in range(rng.randint(0, 7)))
    return s.strip(" \t\r\n")  # epure trims cells; inner spaces and breaks stay
rows, expected = [], []
for i in range(60):
    sheet = sheets[i % 4]
    name = cell() or "x"
    answers = [cell() for _ in columns]
    rows.append([sheet, name] + answers)
    expected.append({"student": name, "answers": dict(zip(columns, answers))})
with open(sys.argv[2], "w", newline="", encoding="utf-8-sig" if bom else "utf-8") as f:
    w = csv.writer(f, delimiter=delimiter, quoting=quoting, lineterminator=newline)
    w.writerow(["sheet", "student"] + columns)
    w.writerows(rows)
# what Python's own reader makes of the file
with open(sys.argv[2], newline="", encoding="utf-8-sig") as f:
    back = list(csv.reader(f, delimiter=delimiter))[1:]
assert [r[1] for r in back] == [e["student"] for e in expected]
json.dump(expected, open(sys.argv[3], "w"))
PY
  timeout 20 "$EPURE" grade --key "$data/key_small.json" --answers "$tmp/answers.csv" --json "$tmp/marks.json" -q >/dev/null 2>"$tmp/err"
  st=$?
  [ "$st" -le 1 ] || { fail "seed $seed: exit $st (124 = hung, killed after 20 s): $(head -3 "$tmp/err")"; continue; }
  python3 - "$tmp/expected.json" "$tmp/marks.json" "$seed" <<'PY' || fail "seed $seed: epure and Python read the CSV differently"
import json, sys
expected = json.load(open(sys.argv[1]))
subs = json.load(open(sys.argv[2]))["submissions"]
assert len(subs) == len(expected), (len(subs), len(expected))
for e, s in zip(expected, subs):
    assert s["student"] == e["student"], (s["line"], s["student"], e["student"])
    given = {q["id"]: q["given"] for q in s["questions"]}
    for id, text in e["answers"].items():
        if id in given:
            assert given[id] == (text if text else None), (s["line"], id, given[id], text)
PY
done

[ "$failed" -eq 0 ] && echo "grade_csv: all checks passed"
exit "$failed"
