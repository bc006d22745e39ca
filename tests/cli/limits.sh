#!/usr/bin/env bash
# The limits of the README ("Limits") on hostile files, one per reader: each gives its clear error
# naming the file, the line or the field, never a crash, nlohmann's raw text or an out-of-memory.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$EPURE_SOURCE_DIR/tests/grading/data"
failed=0
fail() { echo "FAIL: $*"; failed=1; }
says() { grep -q -- "$2" "$1" || fail "$(basename "$1") lacks '$2': $(head -c 600 "$1")"; }
lacks() { if grep -q -- "$2" "$1"; then fail "$(basename "$1") says '$2': $(head -c 600 "$1")"; fi; }

# key.json with fields of the wrong type: the file and the field named (was nlohmann's
# "[json.exception.type_error.306] cannot use value() with number")
python3 - "$data/key_small.json" "$tmp" <<'PY'
import json, sys
key = json.load(open(sys.argv[1]))
cases = {
    "spec-title": lambda k: k["spec"].__setitem__("title", 5),
    "spec-number": lambda k: k.__setitem__("spec", 7),
    "decimals": lambda k: k["spec"].__setitem__("decimals", "two"),
    "follow": lambda k: k["spec"].__setitem__("follow_through", "yes"),
    "seed": lambda k: k.__setitem__("seed", -3),
    "draw": lambda k: k["version"].__setitem__("draw", 1e300),
    "n": lambda k: k["sheets"][0]["exercises"][0].__setitem__("n", 1e300),
    "points": lambda k: k["sheets"][0]["exercises"][0]["questions"][0].__setitem__("points", "1"),
}
for name, change in cases.items():
    k = json.loads(json.dumps(key))
    change(k)
    json.dump(k, open(f"{sys.argv[2]}/{name}.json", "w"))
open(f"{sys.argv[2]}/deep.json", "w").write('{"spec":' + "[" * 100 + "]" * 100 + "}")
PY
declare -A want=(
  [spec-title]="spec-title.json: spec: 'title' must be a string"
  [spec-number]="spec-number.json: spec: expected an object"
  [decimals]="decimals.json: spec: 'decimals' must be an integer from 0 to 6"
  [follow]="follow.json: spec: 'follow_through' must be true or false"
  [seed]="seed.json: 'seed' must be an integer from 0 to"
  [draw]="draw.json: version: 'draw' must be an integer from 0 to 31"
  [n]="n.json: sheet .*: 'n' must be an integer from 1 to 100"
  [points]="points.json: sheet .*: question 1\.[a-z_.A-Z]*: 'points' must be a number"
  [deep]="deep.json: nested deeper than 64 levels"
)
for name in "${!want[@]}"; do
  "$EPURE" grade --key "$tmp/$name.json" --answers "$data/export_fr.csv" -q >"$tmp/$name.out" 2>"$tmp/$name.err"
  s=$?
  [ $s -eq 2 ] || fail "key $name: exit status $s, expected 2"
  says "$tmp/$name.err" "${want[$name]}"
  lacks "$tmp/$name.err" "json.exception"
done

# a spec with 20,000 [[exercise]] tables: refused (was std::bad_alloc under a 2 GiB limit)
python3 -c "print('[[exercise]]\nkind = \"vectors\"\n' * 20000)" >"$tmp/many.toml"
"$EPURE" generate --spec "$tmp/many.toml" --out "$tmp/many" --sheets 2 >"$tmp/many.out" 2>"$tmp/many.err"
[ $? -ne 0 ] || fail "a spec of 20,000 exercises was accepted"
says "$tmp/many.err" "many.toml:1:1: key 'exercise': 20000 \[\[exercise\]\] tables: a spec holds at most 100"
lacks "$tmp/many.err" "bad_alloc"

# epure solve: a 3 MB line and a line nested 100 deep fail alone, the lines after them are solved
good='{"kind":"vectors","u":[1,2],"v":[3,4]}'
python3 - "$tmp/lines.jsonl" "$good" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write('{"kind":"vectors","u":[1,2],"v":[3,4],"pad":"' + "x" * 3_000_000 + '"}\n')
    f.write(sys.argv[2] + "\n")
    f.write('{"kind":' + "[" * 100 + "]" * 100 + "}\n")
    f.write(sys.argv[2] + "\n")
PY
"$EPURE" solve "$tmp/lines.jsonl" >"$tmp/lines.out" 2>"$tmp/lines.err"
[ "$(wc -l <"$tmp/lines.out")" -eq 4 ] || fail "solve: $(wc -l <"$tmp/lines.out") output lines for 4 input lines"
sed -n 1p "$tmp/lines.out" | grep -q '"error":"line: longer than 1048576 bytes' || fail "solve: the long line: $(sed -n 1p "$tmp/lines.out" | head -c 300)"
sed -n 3p "$tmp/lines.out" | grep -q '"error":"line: nested deeper than 32 levels' || fail "solve: the deep line: $(sed -n 3p "$tmp/lines.out")"
for n in 2 4; do
  sed -n ${n}p "$tmp/lines.out" | grep -q '"dot"' || fail "solve: line $n not solved: $(sed -n ${n}p "$tmp/lines.out")"
done

# answers CSV: 5,000 columns, and an unclosed quote running 20 MB
python3 - "$tmp" <<'PY'
import sys
d = sys.argv[1]
open(f"{d}/wide.csv", "w").write("sheet;" + ";".join(f"q{i}" for i in range(5000)) + "\n1000-0001-000X;1\n")
with open(f"{d}/quote.csv", "w") as f:
    f.write("sheet;student\n1000-0001-000X;\"")
    f.write(("x" * 1000 + "\n") * 20_000)
PY
"$EPURE" grade --key "$data/key_small.json" --answers "$tmp/wide.csv" -q >"$tmp/wide.out" 2>"$tmp/wide.err"
[ $? -eq 2 ] || fail "wide.csv: exit status, expected 2"
says "$tmp/wide.err" "wide.csv: line 1: more than 4096 cells in a record"
"$EPURE" grade --key "$data/key_small.json" --answers "$tmp/quote.csv" -q >"$tmp/quote.out" 2>"$tmp/quote.err"
[ $? -eq 2 ] || fail "quote.csv: exit status, expected 2"
says "$tmp/quote.err" "quote.csv: line 2: a record longer than 16 MiB (an unclosed quote?)"

# answers JSON nested 5 million deep: the reading stops at 64 levels (it built a tree of gigabytes)
python3 -c "open('$tmp/deep.json', 'w').write('[' * 5_000_000)"
"$EPURE" grade --key "$data/key_small.json" --answers "$tmp/deep.json" -q >"$tmp/deep-answers.out" 2>"$tmp/deep-answers.err"
s=$?
[ $s -eq 1 ] || [ $s -eq 2 ] || fail "deep.json: exit status $s, expected 1 or 2"
says "$tmp/deep-answers.err" "deep.json.*nested deeper than 64 levels"

# a number past the doubles' range: "not valid JSON", not nlohmann's out_of_range escaping
printf '[{"sheet": "1000-0001-000X", "1.t": 1e400}]\n' >"$tmp/overflow.json"
"$EPURE" grade --key "$data/key_small.json" --answers "$tmp/overflow.json" -q >"$tmp/overflow.out" 2>"$tmp/overflow.err"
says "$tmp/overflow.err" "overflow.json.*not valid JSON after record 0: number overflow parsing '1e400'"
lacks "$tmp/overflow.err" "json.exception"
python3 - "$data/key_small.json" "$tmp/key-overflow.json" <<'PY'
import sys
t = open(sys.argv[1]).read()
i = t.index('"seed"')
open(sys.argv[2], "w").write(t[:i] + '"seed": 1e400, "x' + t[i + 1:])
PY
"$EPURE" grade --key "$tmp/key-overflow.json" --answers "$data/export_fr.csv" -q >"$tmp/key-overflow.out" 2>"$tmp/key-overflow.err"
says "$tmp/key-overflow.err" "key-overflow.json: not valid JSON: number overflow parsing '1e400'"
lacks "$tmp/key-overflow.err" "json.exception"
printf '{"kind":"vectors","u":[1e400,2],"v":[3,4]}\n' | "$EPURE" solve >"$tmp/solve-overflow.out" 2>/dev/null
grep -q '"error":"line: not valid JSON (number overflow parsing' "$tmp/solve-overflow.out" || fail "solve 1e400: $(cat "$tmp/solve-overflow.out")"

[ $failed -eq 0 ] && echo "limits: every hostile file refused clearly"
exit $failed
