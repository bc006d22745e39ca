#!/usr/bin/env bash
# `epure grade` on bad input: nothing silently lost. Each case: the exit status (0 all read,
# 1 something could not be read, 2 nothing graded), the message naming the file and line,
# and rows in = rows reported.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$EPURE_SOURCE_DIR/tests/grading/data"
key="$data/key_small.json"
failed=0
fail() { echo "FAIL: $*"; failed=1; }

# grade NAME [ARGS...]: grades $tmp/NAME.csv against the key, report and JSON beside it
grade() {
  local name=$1; shift
  "$EPURE" grade --key "$key" --answers "$tmp/$name.csv" --report "$tmp/$name.report.csv" --json "$tmp/$name.json" -q "$@" \
    >"$tmp/$name.out" 2>"$tmp/$name.err"
  echo $? >"$tmp/$name.status"
}
status() { cat "$tmp/$1.status"; }
says() { grep -q -- "$2" "$tmp/$1.err" || fail "$1: stderr lacks '$2': $(cat "$tmp/$1.err")"; }
report_rows() { python3 -c "import csv,sys; print(len(list(csv.reader(open(sys.argv[1], encoding='utf-8-sig'))))-1)" "$tmp/$1.report.csv"; }

ok_row() {  # the first row of the realistic export, with the sheet id replaced by $1
  sed -n 2p "$data/export_fr.csv" | tr -d '\r' | sed "s/^1000-0005-002N/$1/"
}
header() { sed -n 1p "$data/export_fr.csv" | tr -d '\r' | sed 's/^\xef\xbb\xbf//'; }

# 1. a mistyped sheet id (check character fails) and an id of another set: named, nearest suggested
{ header; ok_row 1000-0005-002M; ok_row 1000-0007-000Q; ok_row 1000-0005-002N; } >"$tmp/ids.csv"
grade ids
[ "$(status ids)" -eq 1 ] || fail "unknown ids: exit $(status ids)"
says ids "ids.csv:2: error: '1000-0005-002M' is not a valid sheet id: check character"
says ids "nearest sheet of this key is 1000-0005-002N"
says ids "ids.csv:3: error: sheet 1000-0007-000Q belongs to the set of seed 7"
[ "$(report_rows ids)" -eq 3 ] || fail "unknown ids: rows in 3, reported $(report_rows ids)"
grep -q "unknown sheet" "$tmp/ids.report.csv" || fail "unknown ids: not flagged in the report"

# 2. one sheet submitted twice: both marked, both flagged; a warning, not an error
{ header; ok_row 1000-0005-002N; ok_row 1000-0005-002N; } >"$tmp/dup.csv"
grade dup
[ "$(status dup)" -eq 0 ] || fail "duplicate: exit $(status dup)"
says dup "sheet 1000-0005-002N is submitted 2 times (lines 2, 3)"
python3 - "$tmp/dup.json" <<'PY' || fail "duplicate: both rows marked and flagged"
import json, sys
s = json.load(open(sys.argv[1]))["submissions"]
assert len(s) == 2 and all(x["marked"] for x in s)
assert all(any(f["code"] == "duplicate" for f in x["flags"]) for x in s)
PY

# 3. unknown columns, warned once each however many rows; a question-like one is an error
{ header | sed 's/$/;email;2.tt/'; for i in 1 2 3; do ok_row 1000-0005-002N | sed 's/$/;a@b.fr;0,5/'; done; } >"$tmp/cols.csv"
grade cols
[ "$(status cols)" -eq 1 ] || fail "unknown columns: exit $(status cols)"
[ "$(grep -c "'email'" "$tmp/cols.err")" -eq 1 ] || fail "column 'email' not warned exactly once: $(cat "$tmp/cols.err")"
says cols "cols.csv:1: warning: column 38 'email' is not a question"
says cols "cols.csv:1: error: column 39 '2.tt' is not a question of this key"

# 4. values that cannot be read: to check, their points held, the row says which
{ header; ok_row 1000-0005-002N | sed 's/;-0,48;/;environ -0,5;/; s/;oui;1\/6;/;peut-être;1\/6;/'; } >"$tmp/unread.csv"
grade unread
[ "$(status unread)" -eq 1 ] || fail "unreadable: exit $(status unread)"
says unread 'unread.csv:2: error: answers to check (3 points held until a corrections file settles them): 2.t "environ -0,5" is not a number; 3.intersects "peut-être" is not yes or no'
python3 - "$tmp/unread.json" <<'PY' || fail "unreadable: JSON verdicts"
import json, sys
s = json.load(open(sys.argv[1]))["submissions"][0]
q = {x["id"]: x for x in s["questions"]}
assert q["2.t"]["verdict"] == "to_check" and q["2.t"]["points"] == 0
assert q["2.t"]["feedback"].startswith("To check:"), q["2.t"]["feedback"]
assert s["held"] == q["2.t"]["max_points"] + q["3.intersects"]["max_points"] and s["to_check"] == 2, s
PY

# 5. ragged rows: too few cells (the rest not answered), too many (the extra shown)
{ header; ok_row 1000-0005-002N | cut -d';' -f1-10; ok_row 1000-0005-002N | sed 's/$/;surplus/'; } >"$tmp/ragged.csv"
grade ragged
[ "$(status ragged)" -eq 1 ] || fail "ragged: exit $(status ragged)"
says ragged "ragged.csv:2: error: 10 cells where the header has 37"
says ragged 'ragged.csv:3: error: 38 cells where the header has 37: the extra ones are not read: "surplus"'
[ "$(report_rows ragged)" -eq 2 ] || fail "ragged: rows in 2, reported $(report_rows ragged)"

# 6. an empty file; a header without rows; no sheet column
: >"$tmp/empty.csv"
grade empty
[ "$(status empty)" -eq 1 ] || fail "empty file: exit $(status empty)"
says empty "empty.csv: error: the file is empty"
header >"$tmp/headonly.csv"
grade headonly
[ "$(status headonly)" -eq 1 ] || fail "header only: exit $(status headonly)"
says headonly "no answers"
{ echo "name;1.dot"; echo "x;1"; } >"$tmp/nosheet.csv"
grade nosheet
[ "$(status nosheet)" -eq 2 ] || fail "no sheet column: exit $(status nosheet)"
says nosheet "nosheet.csv:1: no sheet column"

# 7. a quote never closed: the rows it swallowed are said
plain_row() { ok_row "$1" | sed 's/;"-y;+x";/;-y +x;/'; }
{ header; plain_row 1000-0005-002N | sed 's/;Lefèvre, Zoé;/;"Lefèvre, Zoé;/'; plain_row 1000-0005-0089; } >"$tmp/quote.csv"
grade quote
[ "$(status quote)" -eq 1 ] || fail "unclosed quote: exit $(status quote)"
says quote "quote.csv:2: error: a quote opened on this row is never closed: lines 2 to 3"

# 8. a key from another generator version: read, marked with its own numbers, said
python3 - "$key" "$tmp/key_v9.json" <<'PY'
import json, sys
k = json.load(open(sys.argv[1])); k["version"] = {"epure": "9.9.9", "draw": 9}
json.dump(k, open(sys.argv[2], "w"))
PY
{ header; ok_row 1000-0005-002N; } >"$tmp/v9.csv"
"$EPURE" grade --key "$tmp/key_v9.json" --answers "$tmp/v9.csv" --feedback "$tmp/v9fb" -q >/dev/null 2>"$tmp/v9.err"
st=$?
[ "$st" -eq 0 ] || fail "other version: exit $st"
grep -q "written by epure 9.9.9 (draw version 9)" "$tmp/v9.err" || fail "other version not said: $(cat "$tmp/v9.err")"
# ids drawn by version 1 are not in a version-9 key's set: said, with the reason
grep -q "sheet 1000-0005-002N" "$tmp/v9.err" && fail "a version-9 key should still mark its own sheet ids"

# 9. a file that is not a key; a key that is missing fields: exit 2, named
echo '{"seed": 1}' >"$tmp/notkey.json"
"$EPURE" grade --key "$tmp/notkey.json" --answers "$tmp/v9.csv" >/dev/null 2>"$tmp/notkey.err"
[ $? -eq 2 ] || fail "not a key: exit status"
grep -q "notkey.json: missing 'spec'" "$tmp/notkey.err" || fail "not a key: $(cat "$tmp/notkey.err")"

# 10. UTF-16 (a spreadsheet's "Unicode text"): refused with the way out
{ header; ok_row 1000-0005-002N; } | iconv -f utf-8 -t utf-16 >"$tmp/u16.csv"
grade u16
[ "$(status u16)" -eq 2 ] || fail "UTF-16: exit $(status u16)"
says u16 "UTF-16"

# 11. Windows-1252 (Excel's plain "CSV"): names read, said once
{ header; ok_row 1000-0005-002N; ok_row 1000-0005-0089 | sed 's/Lefèvre/Lefèbvre/'; } | sed 's/−/-/g; s/√/sqrt/g' |
  iconv -f utf-8 -t windows-1252 >"$tmp/cp.csv"
grade cp
[ "$(status cp)" -eq 1 ] || fail "Windows-1252: exit $(status cp) (0089's answers are for another sheet: errors expected)"
[ "$(grep -c "Windows-1252" "$tmp/cp.err")" -eq 1 ] || fail "Windows-1252 not said exactly once"
grep -q '"Lefèvre, Zoé"' "$tmp/cp.json" || fail "Windows-1252 name not transcoded"

# 12. JSON answers nested a million deep, an object as an answer, a new name on every line:
# no crash (the flattening once recursed as deep as the file), no hang, every row reported
python3 - "$tmp/deep.csv" "$tmp/wide.csv" <<'PY'
import json, sys
deep = "[" * 1000000 + "]" * 1000000
with open(sys.argv[1], "w") as f:
    f.write('{"sheet": "1000-0005-002N", "answers": {"2.t": ' + deep + ', "1.dot": {"a": [1, {"b": 2}]}}}\n')
    f.write('{"sheet": "1000-0005-0089", "answers": {"2.t": "0,5"}}\n')
with open(sys.argv[2], "w") as f:
    for i in range(20000):
        f.write(json.dumps({"sheet": "1000-0005-002N", f"extra{i}": "x"}) + "\n")
PY
printf '[{"sheet": "1000-0005-002N"}, [1, 2], [[[3]]], 7, "x", {"sheet": "1000-0005-0089"}]' >"$tmp/mixed.csv"
grade mixed
[ "$(report_rows mixed)" -eq 6 ] || fail "a JSON array of objects and others: rows in 6, reported $(report_rows mixed)"
says mixed "mixed.csv:3: error: not a JSON object"
grade deep
[ "$(status deep)" -eq 1 ] || fail "deep JSON: exit $(status deep): $(head -c 300 "$tmp/deep.err")"
[ "$(report_rows deep)" -eq 2 ] || fail "deep JSON: rows in 2, reported $(report_rows deep)"
timeout 60 "$EPURE" grade --key "$key" --answers "$tmp/wide.csv" --report "$tmp/wide.report.csv" -q >/dev/null 2>"$tmp/wide.err"
st=$?
[ "$st" -le 1 ] || fail "a new JSON name on each of 20,000 lines: exit $st (124 = over 60 s)"
[ "$(report_rows wide)" -eq 20000 ] || fail "wide JSON: rows in 20000, reported $(report_rows wide)"

# 13. every problem names the file, and a line where it has one
for f in "$tmp"/*.err; do
  while IFS= read -r line; do
    case "$line" in
      "$tmp"/*.csv:[0-9]*": "*|"$tmp"/*.csv": "*|"$tmp"/*.json": "*|*"are counted, not printed"*|"epure grade: "*) ;;
      *) fail "$(basename "$f"): a problem without its file: $line" ;;
    esac
  done <"$f"
done

[ "$failed" -eq 0 ] && echo "grade_bad_input: all checks passed"
exit "$failed"
