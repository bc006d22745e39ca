#!/usr/bin/env bash
# `epure generate --roster`: one sheet per student of a class roster as a spreadsheet exports
# it (a UTF-8 BOM, `;` or `,`, a header line or none, quoted fields), their name and number
# printed on their first page (no number comb then), key.json and layout.json saying whose
# sheet is whose; a roster with errors (a duplicate number, a line without a number, an empty
# file) refused with the file and the line, nothing written; a warning (no name) said, the
# sheets made; the sheets scanned (epure_scan_fixture --set) know their student.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
ok() { echo "ok   $*"; }
bad() { echo "FAIL $*"; fail=1; }

printf '\xef\xbb\xbfNum\xc3\xa9ro \xc3\xa9tudiant;Nom;Courriel\r\n20260001;"Lef\xc3\xa8vre, Zo\xc3\xa9";zoe@example.org\r\n"00412";Martin Paul;\r\n' >"$tmp/fr.csv"
printf '7,Ada Lovelace,ada@example.org\n8,Alan Turing,\n9,Grace Hopper,grace@example.org\n' >"$tmp/en.csv"
"$EPURE" generate --roster "$tmp/fr.csv" --lang fr --format pdf --seed 3 -q --out "$tmp/fr" 2>"$tmp/fr.err" || bad "generate --roster fr.csv: $(cat "$tmp/fr.err")"
"$EPURE" generate --roster "$tmp/en.csv" --format svg,pdf --seed 4 -q --out "$tmp/en" 2>"$tmp/en.err" || bad "generate --roster en.csv: $(cat "$tmp/en.err")"
python3 - "$tmp" <<'PY' && ok "one sheet per student, in the roster's order, in key.json and layout.json" || fail=1
import json, sys
t = sys.argv[1]
want = {"fr": [("20260001", "Lefèvre, Zoé", "zoe@example.org"), ("00412", "Martin Paul", "")],
        "en": [("7", "Ada Lovelace", "ada@example.org"), ("8", "Alan Turing", ""), ("9", "Grace Hopper", "grace@example.org")]}
bad = []
for name, students in want.items():
    key = json.load(open(f"{t}/{name}/key.json"))
    layout = json.load(open(f"{t}/{name}/layout.json"))
    got = [(s["student"]["number"], s["student"]["name"], s["student"].get("email", "")) for s in key["sheets"]]
    if got != students: bad.append(f"{name}: key.json's students {got}")
    got = [(s["student"]["number"], s["student"]["name"]) for s in layout["sheets"]]
    if got != [w[:2] for w in students]: bad.append(f"{name}: layout.json's students {got}")
    for s in layout["sheets"]:
        if any(f["question"] == "student_number" for p in s["pages"] for f in p["fields"]):
            bad.append(f"{name}: sheet {s['sheet']} has a number comb beside its printed number")
if bad:
    print("FAIL roster:", "; ".join(bad)); sys.exit(1)
PY
pdftotext -f 1 -l 1 "$tmp/fr/sheets.pdf" - | grep -q "Lefèvre, Zoé" && pdftotext -f 1 -l 1 "$tmp/fr/sheets.pdf" - | grep -q "20260001" &&
  ok "the student's name and number printed on their first page" || bad "the name is not on the first page"
python3 "$EPURE_SOURCE_DIR/tests/tools/layout_check.py" "$tmp/fr" >/dev/null 2>"$tmp/check.err" && ok "layout.json as the PDF" || bad "layout_check: $(head -5 "$tmp/check.err")"

# the roster's sheets scanned: each sheet's student known from its page code, the number printed
"$EPURE_SCAN_FIXTURE" --key "$tmp/fr/key.json" --set "$tmp/fr" --out "$tmp/scans" --sheets 2 --dpi 150 --degrade none --format png --seed 5 >/dev/null &&
  "$EPURE" scan "$tmp"/scans/scan-*.png --key "$tmp/fr/key.json" --out "$tmp/scanned" -q 2>"$tmp/scan.err"
[ $? -le 1 ] && grep -q "^[^,]*,4,4,,,20260001,printed," "$tmp/scanned/sheets.csv" && grep -q "^[^,]*,4,4,,,00412,printed," "$tmp/scanned/sheets.csv" &&
  ok "scanned: every sheet's student from the roster, the number said printed" || bad "scan of the roster's sheets: $(cat "$tmp/scanned/sheets.csv" "$tmp/scan.err" 2>&1 | head -5)"

# errors: refused, the file and its lines named, nothing written
printf 'number;name\n20260001;A\n20260001;B\n;C\n' >"$tmp/dup.csv"
"$EPURE" generate --roster "$tmp/dup.csv" -q --out "$tmp/dup" 2>"$tmp/dup.err"
[ $? = 2 ] && grep -q "dup.csv:3: error: student number 20260001 is already on line 2" "$tmp/dup.err" &&
  grep -q "dup.csv:4: error: no student number for C" "$tmp/dup.err" && [ ! -e "$tmp/dup" ] &&
  ok "a duplicate number and a line without a number: refused, each line named, nothing written" || bad "dup.csv: $(cat "$tmp/dup.err")"
: >"$tmp/empty.csv"
"$EPURE" generate --roster "$tmp/empty.csv" -q --out "$tmp/empty" 2>"$tmp/empty.err"
[ $? = 2 ] && grep -q "empty.csv: error: no student in the roster" "$tmp/empty.err" && ok "an empty roster refused" || bad "empty.csv: $(cat "$tmp/empty.err")"
"$EPURE" generate --roster "$tmp/en.csv" --sheets 5 -q --out "$tmp/five" 2>"$tmp/five.err"
[ $? = 2 ] && grep -q "a roster makes one sheet per student" "$tmp/five.err" && ok "--sheets other than the roster's size refused" || bad "--sheets 5: $(cat "$tmp/five.err")"
# a warning: the sheets are made
printf '1;Ann\n2;\n' >"$tmp/noname.csv"
"$EPURE" generate --roster "$tmp/noname.csv" --format pdf -q --out "$tmp/noname" 2>"$tmp/noname.err" &&
  grep -q "noname.csv:2: warning: no name for student 2" "$tmp/noname.err" && [ -s "$tmp/noname/sheets.pdf" ] &&
  ok "a line without a name: a warning, the sheets made" || bad "noname.csv: $(cat "$tmp/noname.err")"
exit $fail
