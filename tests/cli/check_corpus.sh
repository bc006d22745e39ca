#!/usr/bin/env bash
# epure starter and epure check on the right and buggy corpus (tests/check/corpus): the starter
# compiles, in both languages, with the same code; the course's functions, mended, pass; each
# buggy file's classic bugs are named (corpus/expected.json); marks.csv, summary.txt, report.json
# and the feedback pages (HTML with the figures inline, PDF that qpdf calls sound) are written.
set -euo pipefail
: "${EPURE:?}" "${EPURE_SOURCE_DIR:?}"
tmp=$(mktemp -d)
chmod 711 "$tmp"
trap 'rm -rf "$tmp"' EXIT
corpus="$EPURE_SOURCE_DIR/tests/check/corpus"

# ---- the starter -------------------------------------------------------------------------------
for lang in en fr; do
  "$EPURE" starter --lang "$lang" --out "$tmp/starter-$lang" >/dev/null
  (cd "$tmp/starter-$lang" && gcc -std=c11 -Wall -Wextra -Werror -c raytracer.c -o raytracer.o)  # never -o /dev/null: as root, the assembler replaces it with a file
  for h in raytracer.h g2x.h g3x.h; do
    gcc -std=c11 -DEPURE_CHECK -E -P -x c "$tmp/starter-$lang/$h" -I "$tmp/starter-$lang" > "$tmp/$lang-$h.i"
  done
done
for h in raytracer.h g2x.h g3x.h; do
  cmp -s "$tmp/en-$h.i" "$tmp/fr-$h.i" || { echo "FAIL: $h: the English and French starters differ in code"; diff "$tmp/en-$h.i" "$tmp/fr-$h.i" | head; exit 1; }
done
# it does not overwrite a student's work
echo "/* mine */" > "$tmp/starter-fr/raytracer.c"
if "$EPURE" starter --lang fr --out "$tmp/starter-fr" >/dev/null 2>&1; then echo "FAIL: starter overwrote without --force"; exit 1; fi
grep -q mine "$tmp/starter-fr/raytracer.c" || { echo "FAIL: raytracer.c overwritten"; exit 1; }
# the course's mended snippets compile against the starter's headers, on their own, with a main
cp "$corpus/right/course_mended.c" "$tmp/starter-en/mended.c"
cat > "$tmp/starter-en/main.c" <<'C'
#include <stdio.h>
#include "raytracer.h"
int main(void) {
  G2Xpoint J; G2Xvector N;
  bool hit = rayon_inter_cercle_canonique(&J, &N, (G2Xpoint){-3, 0}, (G2Xvector){1, 0});
  printf("%d %g %g\n", hit, J.x, J.y);
  return !(hit && J.x == -1 && J.y == 0);
}
C
(cd "$tmp/starter-en" && gcc -std=c11 -Wall -Wextra -Werror mended.c main.c -lm -o demo && ./demo >/dev/null)

# ---- the corpus --------------------------------------------------------------------------------
mkdir "$tmp/work" && chmod 711 "$tmp/work"
cp "$EPURE_SOURCE_DIR/templates/check/starter/fr/raytracer.c" "$tmp/starter_untouched.c"
start=$(date +%s)
TMPDIR="$tmp/work" "$EPURE" check "$corpus/right" "$corpus/buggy" "$tmp/starter_untouched.c" --out "$tmp/out" \
  --lang fr --jobs 2 --quiet
echo "corpus checked in $(( $(date +%s) - start )) s"

python3 - "$tmp/out" "$corpus/expected.json" <<'PY'
import csv, json, os, sys
out, expected_path = sys.argv[1], sys.argv[2]
report = json.load(open(os.path.join(out, "report.json")))
expected = json.load(open(expected_path))
names = ["Projection", "InterSegments", "rayon_inter_cercle", "rayon_inter_cercle_canonique",
         "rayon_inter_carre_canonique", "rayon_inter_ellipse", "rayon_inter_rectangle",
         "rayon_inter_sphere", "rayon_inter_cube_canonique"]
failures = 0
def fail(msg):
    global failures
    print("FAIL:", msg); failures += 1
seen = set()
for f in report["files"]:
    rel = "/".join(f["file"].split("/")[-2:])
    if rel.endswith("starter_untouched.c"):
        if f["functions"] or sorted(f["not_written"]) != sorted(names):
            fail(f"the untouched starter: functions {list(f['functions'])}, not written {f['not_written']}")
        continue
    seen.add(rel)
    want = expected[rel]
    for name in names:
        fn = f["functions"].get(name)
        if fn is None:
            fail(f"{rel}: {name} not checked"); continue
        if name in want:
            if fn["verdict"] != "wrong" or fn["bugs"] != want[name] or fn["bug"] != want[name][0]:
                fail(f"{rel}: {name}: {fn['verdict']} {fn['bugs']}, expected wrong {want[name]}")
            elif not fn["failures"] or any(k not in fn["failures"][0] for k in ("input", "expected", "got")):
                fail(f"{rel}: {name}: no failing case with input, expected and got")
        elif fn["verdict"] != "passed" or fn["failed"] != 0 or fn["bug"] is not None:
            fail(f"{rel}: {name}: {fn['verdict']} ({fn['passed']}/{fn['cases']}), expected passed")
        if fn["passed"] + fn["failed"] != fn["cases"] or fn["cases"] < 140:
            fail(f"{rel}: {name}: {fn['cases']} cases, {fn['passed']} passed, {fn['failed']} failed")
for rel in expected:
    if rel != "_" and rel not in seen: fail(f"{rel} not in the report")
# marks.csv: a gradebook's columns
rows = list(csv.reader(open(os.path.join(out, "marks.csv"), newline="", encoding="utf-8")))
if rows[0] != ["sheet", "file", "student"] + names + ["total"]: fail(f"marks.csv header {rows[0]}")
if len(rows) != len(report["files"]) + 1: fail("marks.csv: not one row per file")
for row in rows[1:]:
    if row[1] == "course_mended.c" and (row[2] != "Course, mended" or row[-1] != "9"): fail(f"marks.csv: {row}")
    if abs(sum(float(x) for x in row[3:-1]) - float(row[-1])) > 0.02: fail(f"marks.csv: total of {row}")
# feedback pages: one HTML and one PDF per file; a failing function's figures inline
for f in report["files"]:
    base = os.path.join(out, f["feedback"])
    html = open(base).read()
    if not os.path.exists(base[:-5] + ".pdf"): fail(f"{base}: no PDF")
    if any(fn["verdict"] == "wrong" for fn in f["functions"].values()) and "<svg" not in html:
        fail(f"{base}: a wrong function and no figure")
summary = open(os.path.join(out, "summary.txt"), encoding="utf-8").read()
if "inside_as_miss" not in summary or "réussie" not in summary: fail("summary.txt")
print(f"{len(report['files'])} files, {failures} failures")
sys.exit(1 if failures else 0)
PY

# the PDFs are sound, and the verbatim course's page is drawn (a look at it: feedback/course_verbatim.pdf)
for pdf in "$tmp/out/feedback/course_verbatim.pdf" "$tmp/out/feedback/normals.pdf"; do
  if command -v qpdf >/dev/null; then qpdf --check "$pdf" >/dev/null; fi
  if command -v pdftotext >/dev/null; then
    text=$(pdftotext "$pdf" -)
    grep -q "rayon_inter_carre_canonique" <<<"$text" || { echo "FAIL: $pdf: text"; exit 1; }
  fi
done
if command -v pdftotext >/dev/null; then
  text=$(pdftotext "$tmp/out/feedback/course_verbatim.pdf" - | tr '\n' ' ')
  grep -q "parenthèse" <<<"$text" || { echo "FAIL: the square's bug sentence is not on the page"; exit 1; }
fi
echo "starter, corpus, marks and feedback pages: ok"
