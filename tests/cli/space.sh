#!/usr/bin/env bash
# The course in space (issue 13): `epure generate --spec builtin:3d` writes sheets and keys in
# both languages; every solution in key.json equals `epure solve` on its instance; a class set of
# 30 shows every branch of each kind; no text over text on any page (tests/tools/page_collisions.py)
# at every difficulty; `epure preview ray_sphere --branch hit` works.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
export SOURCE_DATE_EPOCH=1700000000

"$EPURE" generate --spec builtin:3d --sheets 30 --seed 7 --format svg,pdf --out "$tmp/a" --quiet --jobs 2 ||
  fail "generate --spec builtin:3d"
"$EPURE" kinds --json > "$tmp/kinds.json" || fail "epure kinds --json"
python3 - "$tmp/a/key.json" "$tmp/a/instances.jsonl" "$tmp/a/solutions.jsonl" "$tmp/kinds.json" <<'PY' || fail "key.json checks"
import json, sys, collections
key = json.load(open(sys.argv[1]))
sheets = key["sheets"]
assert len(sheets) == 30
branches = collections.defaultdict(collections.Counter)
with open(sys.argv[2], "w") as inst, open(sys.argv[3], "w") as sol:
    for s in sheets:
        for e in s["exercises"]:
            inst.write(json.dumps(e["instance"], separators=(",", ":")) + "\n")
            sol.write(json.dumps(e["solution"], separators=(",", ":")) + "\n")
            branches[e["kind"]][e["branch"]] += 1
weights = {k["name"]: {b: w for b, w in k["branches"].items() if w > 0} for k in json.load(open(sys.argv[4]))}
assert set(branches) == {"vectors_3d", "ray_sphere", "ray_cube"}, branches.keys()
for kind, counts in sorted(branches.items()):
    print(kind, dict(counts))
    for b in weights[kind]:
        assert counts[b] > 0, (kind, b, "never drawn in 30 sheets")
PY
"$EPURE" solve "$tmp/a/instances.jsonl" > "$tmp/a/resolved.jsonl" || fail "solve refused a generated instance"
python3 - "$tmp/a/solutions.jsonl" "$tmp/a/resolved.jsonl" <<'PY' || fail "a key.json solution differs from epure solve"
import json, sys
a = [json.loads(l) for l in open(sys.argv[1])]
b = [json.loads(l) for l in open(sys.argv[2])]
assert len(a) == len(b) == 90, (len(a), len(b))
for i, (x, y) in enumerate(zip(a, b)):
    assert x == y, (i, x, y)
# the 3D vectors are the contract's vectors with three components: cross is [x, y, z]
assert any(x["kind"] == "vectors" and len(x["cross"]) == 3 for x in a)
print(len(a), "solutions equal to epure solve")
PY
xmllint --noout "$tmp/a"/sheets/*.svg "$tmp/a"/keys/*.svg || fail "xmllint"

# grading: the key's own answers earn full marks, on the key.json and on keys rebuilt from the
# spec; a sign error in the middle component of u∧v is named
python3 - "$tmp/a/key.json" "$tmp/answers.csv" <<'PY' || fail "answers from the key"
import json, sys, csv
key = json.load(open(sys.argv[1]))
def cell(e):
    if isinstance(e, bool): return "yes" if e else "no"
    if isinstance(e, list): return " ".join(e) if e else "none"
    return str(e)
rows, ids = [], []
for s in key["sheets"][:6]:
    for e in s["exercises"]:
        for q in e["questions"]:
            if q["id"] not in ids: ids.append(q["id"])
for s in key["sheets"][:6]:
    right = {q["id"]: cell(q["expected"]) for e in s["exercises"] for q in e["questions"]}
    rows.append(dict(right, sheet=s["id"], student="right " + s["id"]))
    wrong = dict(right, sheet=s["id"], student="middle " + s["id"])
    y = float(right["1.cross.y"])
    if y != 0:
        wrong["1.cross.y"] = str(-y)
        rows.append(wrong)
with open(sys.argv[2], "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=["sheet", "student"] + ids)
    w.writeheader()
    for r in rows: w.writerow(r)
PY
for source in "--key $tmp/a/key.json" "--spec builtin:3d"; do
  "$EPURE" grade $source --answers "$tmp/answers.csv" --json "$tmp/marks.json" -q 2>/dev/null || fail "grade $source"
  python3 - "$tmp/marks.json" <<'PY' || fail "marks of the key's own answers ($source)"
import json, sys
subs = json.load(open(sys.argv[1]))["submissions"]
assert subs, "no submission marked"
middle = 0
for s in subs:
    if s["student"].startswith("right"):
        assert abs(s["score"] - s["max"]) < 1e-9, (s["student"], s["score"], s["max"])
    else:
        middle += 1
        named = [q["mistake"] for q in s["questions"] if q["verdict"] == "wrong"]
        assert named == ["cross_middle_sign"], (s["student"], named)
assert middle > 0
print(len(subs), "submissions marked as expected")
PY
done

# French and every difficulty, and no text over text on any page
for d in easy standard hard; do
  for lang in en fr; do
    "$EPURE" generate --spec builtin:3d --sheets 10 --seed 11 --lang "$lang" --difficulty "$d" --format pdf \
      --out "$tmp/$lang-$d" --quiet --jobs 2 || fail "generate --spec builtin:3d --lang $lang --difficulty $d"
  done
done
grep -q 'Exercice' <(pdftotext "$tmp/fr-easy/sheets.pdf" -) || fail "French 3D sheet has no 'Exercice'"
python3 "$EPURE_SOURCE_DIR/tests/tools/page_collisions.py" "$tmp/a/sheets.pdf" "$tmp/a/keys.pdf" "$tmp"/*-*/sheets.pdf \
  "$tmp"/*-*/keys.pdf || fail "text printed over text (above)"

# preview of a 3D kind's branch
"$EPURE" preview ray_sphere --branch hit --out "$tmp/preview" >/dev/null || fail "preview ray_sphere --branch hit"
ls "$tmp/preview"/ray_sphere-*.png >/dev/null 2>&1 || fail "preview wrote no PNG"
"$EPURE" generate --spec builtin:4d --out "$tmp/bad" --quiet 2>/dev/null && fail "an unknown builtin spec was read as a file"
# the kind model's count: outside src/geometry and src/solve, each 3D kind is named in at most two
# files under src/ (its own and the registry); src/check/functions.cpp names the contract's kind
# each of the course's C functions is checked and drawn as (epure check), as src/solve does
for kind in ray_sphere ray_cube vectors_3d; do
  n=$(grep -rl "$kind" "$EPURE_SOURCE_DIR/src" --exclude-dir=geometry --exclude-dir=solve |
      grep -vc "/src/check/functions.cpp$" || true)
  [ "$n" -le 2 ] || fail "$kind is named in $n files under src/ (at most 2)"
done
echo "space: ok"
