#!/usr/bin/env bash
# `epure generate` end to end: files written, byte-identical across runs and job counts, every
# solution in key.json equal to `epure solve` on its instance, every SVG well-formed (xmllint)
# and renderable (rsvg-convert), branches at their asked rates, bad specs refused with file:line.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$EPURE" generate --sheets 30 --seed 42 --out "$tmp/a" --quiet --jobs 1 || fail "generate exit status"
"$EPURE" generate --sheets 30 --seed 42 --out "$tmp/b" --quiet --jobs 2 || fail "generate --jobs 2"
"$EPURE" generate --sheets 30 --seed 42 --out "$tmp/c" --quiet || fail "generate (default jobs)"
diff -r "$tmp/a" "$tmp/b" >/dev/null || fail "--jobs 1 and --jobs 2 differ"
diff -r "$tmp/a" "$tmp/c" >/dev/null || fail "two runs differ"
# The class-set PDFs alone: with two jobs the caller draws sheets.pdf between batches, with three
# it has a thread of its own (generate.cpp); 30 sheets make three batches (8, 16, 6).
for j in 1 2 3; do
  "$EPURE" generate --sheets 30 --seed 42 --format pdf --out "$tmp/pdf$j" --quiet --jobs $j || fail "generate --format pdf --jobs $j"
done
for j in 2 3; do
  cmp -s "$tmp/pdf1/sheets.pdf" "$tmp/pdf$j/sheets.pdf" && cmp -s "$tmp/pdf1/keys.pdf" "$tmp/pdf$j/keys.pdf" &&
    cmp -s "$tmp/pdf1/key.json" "$tmp/pdf$j/key.json" || fail "--format pdf: --jobs 1 and --jobs $j differ"
done
rm -rf "$tmp"/pdf?

[ "$(ls "$tmp/a/sheets" | wc -l)" -eq 30 ] || fail "expected 30 sheets"
[ "$(ls "$tmp/a/keys" | wc -l)" -eq 30 ] || fail "expected 30 keys"
[ -s "$tmp/a/index.html" ] || fail "no index.html"
ls "$tmp/a" | grep -q '\.tmp$' && fail "a temporary file was left behind"

# key.json: structure, ids, solutions == epure solve(instance), branch rates, questions
"$EPURE" kinds --json > "$tmp/kinds.json" || fail "epure kinds --json"
python3 - "$tmp/a/key.json" "$tmp/a/instances.jsonl" "$tmp/a/solutions.jsonl" "$tmp/kinds.json" <<'PY' || fail "key.json checks"
import json, sys, collections
key = json.load(open(sys.argv[1]))
assert set(key) == {"spec", "seed", "version", "sheets"}, key.keys()
assert key["seed"] == 42
sheets = key["sheets"]
assert len(sheets) == 30
ids = [s["id"] for s in sheets]
assert len(set(ids)) == 30, "sheet ids repeat"
with open(sys.argv[2], "w") as inst, open(sys.argv[3], "w") as sol:
    for s in sheets:
        for e in s["exercises"]:
            inst.write(json.dumps(e["instance"], separators=(",", ":")) + "\n")
            sol.write(json.dumps(e["solution"], separators=(",", ":")) + "\n")
            for q in e["questions"]:
                # one numbering: the course's exercise numbers, as the sheet heads them
                number = e.get("number", str(e["n"]))
                assert number == ["P", "1", "2", "3", "4", "3.3", "4.3"][e["n"] - 1], (e["n"], number)
                assert q["id"].startswith(f'{number}.'), q["id"]
                assert {"id", "expected", "tolerance", "points"} <= set(q), q
                t = q["tolerance"]
                assert t["rule"] in ("exact", "isclose", "distance"), t
                if t["rule"] != "exact":
                    assert t["abs"] > 0, q
# no two sheets share an instance of an exercise
by_slot = collections.defaultdict(set)
for s in sheets:
    for e in s["exercises"]:
        text = json.dumps(e["instance"], sort_keys=True)
        assert text not in by_slot[e["n"]], f"exercise {e['n']} repeats an instance"
        by_slot[e["n"]].add(text)
# every branch of every exercise appears in a class set of 30 under the course's weights
branches = collections.defaultdict(collections.Counter)
for s in sheets:
    for e in s["exercises"]:
        branches[(e["n"], e["kind"])][e["branch"]] += 1
# the kinds' default weights (the course's spec overrides none): every branch appears, each
# within 2 sheets of its share of 30
weights = {k["name"]: {b: w for b, w in k["branches"].items() if w > 0} for k in json.load(open(sys.argv[4]))}
assert len(weights) >= 7, weights
for (n, kind), counts in sorted(branches.items()):
    print(n, kind, dict(counts))
    w = weights[kind]
    for b, weight in w.items():
        share = 30 * weight / sum(w.values())
        assert abs(counts[b] - share) <= 2, (kind, b, counts[b], share)
PY
"$EPURE" solve "$tmp/a/instances.jsonl" > "$tmp/a/resolved.jsonl" || fail "solve refused a generated instance"
python3 - "$tmp/a/solutions.jsonl" "$tmp/a/resolved.jsonl" <<'PY' || fail "a key.json solution differs from epure solve"
import json, sys
a = [json.loads(l) for l in open(sys.argv[1])]
b = [json.loads(l) for l in open(sys.argv[2])]
assert len(a) == len(b)
for i, (x, y) in enumerate(zip(a, b)):
    assert x == y, (i, x, y)
print(len(a), "solutions equal to epure solve")
PY

# every SVG is well-formed, and a few render
xmllint --noout "$tmp/a"/sheets/*.svg "$tmp/a"/keys/*.svg || fail "xmllint"
for f in $(ls "$tmp/a"/sheets/*.svg | head -3) $(ls "$tmp/a"/keys/*.svg | head -3); do
  rsvg-convert -o "$tmp/page.png" "$f" || fail "rsvg-convert $f"
done

# French, every difficulty
for d in easy standard hard; do
  "$EPURE" generate --sheets 6 --seed 3 --lang fr --difficulty "$d" --out "$tmp/fr-$d" --quiet || fail "generate --lang fr --difficulty $d"
  xmllint --noout "$tmp/fr-$d"/sheets/*.svg "$tmp/fr-$d"/keys/*.svg || fail "xmllint fr $d"
done
grep -q 'Exercice' "$tmp/fr-easy"/sheets/*.svg || fail "French sheet has no 'Exercice'"

# bad input: spec errors name file:line:key, exit 2; nothing half-written
printf 'title = "x"\n[[exercise]]\nkind = "ray_torus"\n' > "$tmp/bad.toml"
"$EPURE" generate --spec "$tmp/bad.toml" --out "$tmp/bad" --quiet 2> "$tmp/err"; status=$?
[ "$status" -eq 2 ] || fail "bad spec: exit $status, expected 2"
grep -q "bad.toml:3:.*exercise\[1\].kind" "$tmp/err" || { cat "$tmp/err"; fail "bad spec message"; }
"$EPURE" generate --sheets 0 --out "$tmp/zero" --quiet 2>/dev/null && fail "--sheets 0 accepted"
# a set that cannot hold that many distinct sheets (the default course at easy runs the vectors'
# branches out after 549): said, exit 2, and nothing created, not even the empty sheets/ and keys/
# directories generate used to leave behind
"$EPURE" generate --difficulty easy --sheets 550 --seed 11 --out "$tmp/full" --quiet 2> "$tmp/err"; status=$?
[ "$status" -eq 2 ] || fail "a set too large for its branches: exit $status, expected 2"
grep -q "run out of new instances after 549 sheets" "$tmp/err" || { cat "$tmp/err"; fail "a set too large: message"; }
[ ! -e "$tmp/full" ] || fail "a set that cannot be drawn left $(ls -A "$tmp/full" | tr '\n' ' ')behind"
echo "generate: ok"
