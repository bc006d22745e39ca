#!/usr/bin/env bash
# `epure export moodle|qti` end to end, for an English and a French class set of 30 sheets of
# the course: every Moodle question read with the importer's Cloze grammar and checked against
# the key (tests/tools/moodle_cloze.py), every named mistake answer marked by `epure grade` and
# by Moodle's rules with the same verdict (tests/tools/mistakes_vs_grading.py), the QTI package
# validated with xmllint against IMS's schemas (tests/qti-xsd/, copied from IMS's distribution)
# and checked against its manifest and the key (tests/tools/qti_check.py); reruns byte-identical
# (in another time zone too); SVG diagrams; the errors for a set that cannot be exported.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
tools="$EPURE_SOURCE_DIR/tests/tools"
xsd="$EPURE_SOURCE_DIR/tests/qti-xsd"
failed=0
fail() { echo "FAIL: $*"; failed=1; }

for lang in en fr; do
  set="$tmp/set-$lang"
  seed=$([ "$lang" = en ] && echo 1 || echo 2)
  "$EPURE" generate --sheets 30 --seed "$seed" --lang "$lang" --format svg --out "$set" --quiet \
    || { fail "$lang: generate"; continue; }
  "$EPURE" export moodle --set "$set" >"$tmp/out" 2>"$tmp/err" || fail "$lang: export moodle: $(cat "$tmp/err")"
  grep -q "210 questions" "$tmp/out" || fail "$lang: export moodle says: $(cat "$tmp/out")"
  [ -s "$set/moodle.xml" ] || fail "$lang: no $set/moodle.xml"
  "$EPURE" export qti --set "$set" >/dev/null 2>"$tmp/err" || fail "$lang: export qti: $(cat "$tmp/err")"
  [ -s "$set/qti.zip" ] || fail "$lang: no $set/qti.zip"

  # byte-identical reruns (the zip's timestamps are fixed DOS dates, whatever the time zone)
  "$EPURE" export moodle --set "$set" --out "$tmp/again.xml" >/dev/null
  cmp -s "$set/moodle.xml" "$tmp/again.xml" || fail "$lang: moodle.xml differs on a rerun"
  TZ=Pacific/Kiritimati "$EPURE" export qti --set "$set" --out "$tmp/again.zip" >/dev/null
  cmp -s "$set/qti.zip" "$tmp/again.zip" || fail "$lang: qti.zip differs on a rerun in another time zone"

  python3 "$tools/moodle_cloze.py" "$set/moodle.xml" "$set/key.json" \
    "$EPURE_SOURCE_DIR/templates/text/$lang/grading.toml" --summary >"$tmp/cloze" \
    || { cat "$tmp/cloze"; fail "$lang: the Cloze questions"; }
  cat "$tmp/cloze"
  # every named mistake the set's kinds declare is offered somewhere in 30 sheets
  python3 - "$tmp/cloze" <<PY || fail "$lang: a named mistake is never offered"
import json, re, subprocess, sys
seen = set(re.search(r'mistakes: ([^)]*)\)', open(sys.argv[1]).read()).group(1).split(', '))
kinds = json.loads(subprocess.run(["$EPURE", "kinds", "--json"], capture_output=True, text=True).stdout)
kinds = kinds if isinstance(kinds, list) else kinds["kinds"]
in_set = {e["kind"] for s in json.load(open("$set/key.json"))["sheets"] for e in s["exercises"]}
declared = {m for k in kinds if k["name"] in in_set for m in k.get("mistakes", [])}
missing = declared - seen
assert not missing, f"never offered: {sorted(missing)}"
PY
  mkdir -p "$tmp/work-$lang"
  python3 "$tools/mistakes_vs_grading.py" "$EPURE" "$set/moodle.xml" "$set/key.json" \
    "$EPURE_SOURCE_DIR/templates/text/$lang/grading.toml" "$tmp/work-$lang" >"$tmp/vs" \
    || { cat "$tmp/vs"; fail "$lang: Moodle's mistakes against epure grade"; }
  tail -1 "$tmp/vs"

  python3 "$tools/qti_check.py" "$set/qti.zip" "$set/key.json" "$tmp/qti-$lang" >"$tmp/qti" \
    || { cat "$tmp/qti"; fail "$lang: the QTI package"; }
  cat "$tmp/qti"
  (cd "$tmp/qti-$lang" && xmllint --noout --nonet --schema "$xsd/imscp_v1p1.xsd" imsmanifest.xml) 2>"$tmp/lint" \
    || { head -5 "$tmp/lint"; fail "$lang: imsmanifest.xml against imscp_v1p1.xsd"; }
  (cd "$tmp/qti-$lang" && xmllint --noout --nonet --schema "$xsd/qtiv2p1/imsqti_v2p1.xsd" test.xml items/*.xml) \
    2>"$tmp/lint" || { grep -v validates "$tmp/lint" | head -5; fail "$lang: the items and the test against imsqti_v2p1.xsd"; }
  n=$(grep -c ' validates$' "$tmp/lint")
  [ "$n" -eq 211 ] || fail "$lang: $n of 211 QTI files validate"
done

# The course in space (vectors in ℝ³, ray/sphere, ray/cube: 64 sets of faces), and a
# spec whose points are marked as a whole (QTI's distance test); French for the first.
mkdir -p "$tmp/wp" && cat >"$tmp/wp/spec.toml" <<'TOML'
title = "Whole points"
[[exercise]]
kind = "projection"
questions = { P = { whole_point = true, abs = 0.02 } }
[[exercise]]
kind = "ray_circle"
questions = { I = { whole_point = true }, N = { whole_point = true } }
TOML
for extra in "3d fr builtin:3d" "wp en $tmp/wp/spec.toml"; do
  set -- $extra
  name=$1 lang=$2 spec=$3 set="$tmp/set-$1"
  "$EPURE" generate --spec "$spec" --sheets 12 --seed 3 --lang "$lang" --format svg --out "$set" --quiet \
    || { fail "$name: generate"; continue; }
  "$EPURE" export moodle --set "$set" >/dev/null 2>"$tmp/err" || fail "$name: export moodle: $(cat "$tmp/err")"
  "$EPURE" export qti --set "$set" >/dev/null 2>"$tmp/err" || fail "$name: export qti: $(cat "$tmp/err")"
  python3 "$tools/moodle_cloze.py" "$set/moodle.xml" "$set/key.json" \
    "$EPURE_SOURCE_DIR/templates/text/$lang/grading.toml" --summary >"$tmp/cloze" \
    || { cat "$tmp/cloze"; fail "$name: the Cloze questions"; }
  cat "$tmp/cloze"
  python3 "$tools/qti_check.py" "$set/qti.zip" "$set/key.json" "$tmp/qti-$name" >"$tmp/qti" \
    || { cat "$tmp/qti"; fail "$name: the QTI package"; }
  cat "$tmp/qti"
  (cd "$tmp/qti-$name" && xmllint --noout --nonet --schema "$xsd/qtiv2p1/imsqti_v2p1.xsd" test.xml items/*.xml) \
    2>"$tmp/lint" || { grep -v validates "$tmp/lint" | head -5; fail "$name: the items against imsqti_v2p1.xsd"; }
done
python3 - "$tools" "$tmp/set-3d/moodle.xml" <<'PY' || fail "3d: the cube's faces are not one list of its 64 sets of faces"
import sys, xml.etree.ElementTree as ET
sys.path.insert(0, sys.argv[1])
from moodle_cloze import extract
lists = [len(p['alternatives']) for q in ET.parse(sys.argv[2]).getroot().findall('question')
         if q.get('type') == 'multianswer' for p in extract(q.findtext('questiontext/text'))[0]
         if p['type'] == 'multichoice' and any('+z' in a.get('text', '') for a in p['alternatives'])]
assert lists and all(n == 64 for n in lists), lists
PY
grep -q '<lte><sum><power>' "$tmp/qti-wp/items/"*-1.xml || fail "wp: no point marked by its distance in QTI"

# SVG diagrams, and another language than the set's
set="$tmp/set-en"
"$EPURE" export moodle --set "$set" --image svg --lang fr --out "$tmp/svg.xml" >/dev/null 2>"$tmp/err" \
  || fail "svg: $(cat "$tmp/err")"
python3 "$tools/moodle_cloze.py" "$tmp/svg.xml" "$set/key.json" "$EPURE_SOURCE_DIR/templates/text/fr/grading.toml" \
  >"$tmp/cloze" || { cat "$tmp/cloze"; fail "svg, fr: the Cloze questions"; }
grep -q 'Exercice\|exercice\|Produit' "$tmp/svg.xml" || fail "--lang fr: the questions are not in French"
grep -q '\.svg" path="/" encoding="base64"' "$tmp/svg.xml" || fail "--image svg: no SVG embedded"

# errors name the file and what is wrong; nothing is written
"$EPURE" export moodle --set "$tmp/nowhere" >"$tmp/out" 2>"$tmp/err"; st=$?
[ "$st" -eq 2 ] || fail "no key.json: exit $st, expected 2"
grep -q "nowhere/key.json" "$tmp/err" || fail "no key.json: the message does not name the file: $(cat "$tmp/err")"
mkdir -p "$tmp/old" && sed 's/"draw":[0-9]*/"draw":29/' "$set/key.json" >"$tmp/old/key.json"
"$EPURE" export qti --set "$tmp/old" >"$tmp/out" 2>"$tmp/err"; st=$?
[ "$st" -eq 2 ] || fail "another generator version: exit $st, expected 2"
grep -q "old/key.json.*version 29" "$tmp/err" || fail "another generator version: $(cat "$tmp/err")"
[ -e "$tmp/old/qti.zip" ] && fail "another generator version: a qti.zip was written"
mkdir -p "$tmp/empty" && python3 - "$set/key.json" "$tmp/empty/key.json" <<'PY'
import json, sys
k = json.load(open(sys.argv[1])); k["sheets"] = []
json.dump(k, open(sys.argv[2], "w"))
PY
"$EPURE" export moodle --set "$tmp/empty" >"$tmp/out" 2>"$tmp/err"; st=$?
[ "$st" -eq 2 ] || fail "no exercises: exit $st, expected 2"
grep -q "empty/key.json.*no \(sheets\|exercises\)" "$tmp/err" || fail "no exercises: $(cat "$tmp/err")"
"$EPURE" export moodle --set "$set" --image gif >/dev/null 2>&1 && fail "--image gif accepted"

exit $failed
