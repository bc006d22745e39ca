#!/usr/bin/env bash
# `epure generate --format pdf` end to end: the class-set PDFs pass qpdf --check; their page
# counts are the layout's (the SVG pages), with blank pages under --duplex so that every sheet
# starts on an odd page; pdftotext finds every sheet's id and statements, French accents
# included; pdffonts lists embedded fonts only; the metadata comes from the spec and
# SOURCE_DATE_EPOCH; the same spec and seed give byte-identical PDFs across runs and job counts;
# every page's QR code reads back as its page code; a PDF page and the SVG page of the same
# sheet agree pixel-wise (and two different sheets do not); --split, --paper letter and
# `epure preview` write what they say. With the explorer's page built, the keys' PDFs link each
# exercise to explore.html#<sheet id>.<n> (a /Link annotation read back with qpdf --json) and
# still pass qpdf --check.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
for tool in qpdf pdfinfo pdftotext pdffonts pdftoppm rsvg-convert zbarimg python3; do
  command -v $tool >/dev/null || fail "$tool missing (see .ci/bootstrap)"
done
compare=$EPURE_SOURCE_DIR/tests/tools/png_compare.py
export SOURCE_DATE_EPOCH=1700000000  # 2023-11-14 22:13:20 UTC

gen() { "$EPURE" generate --quiet "$@" || fail "generate $*"; }
gen --format svg,pdf --sheets 6 --seed 11 --out "$tmp/a" --jobs 1
gen --format svg,pdf --sheets 6 --seed 11 --out "$tmp/b" --jobs 2
gen --format svg,pdf --sheets 6 --seed 11 --out "$tmp/d" --jobs 2 --duplex
for f in sheets keys; do
  cmp -s "$tmp/a/$f.pdf" "$tmp/b/$f.pdf" || fail "$f.pdf differs between --jobs 1 and --jobs 2 (or two runs)"
  qpdf --check "$tmp/a/$f.pdf" >/dev/null || fail "qpdf --check $f.pdf"
  qpdf --check "$tmp/d/$f.pdf" >/dev/null || fail "qpdf --check $f.pdf (duplex)"
done

# Links to the explorer (only when the set has explore.html): one /Link per exercise of keys.pdf,
# in order, on the page where its heading is, inside the page; none in sheets.pdf. The same
# with --duplex (blank pages between sheets) and in the --split keys (../explore.html, one level
# below the set).
links=$EPURE_SOURCE_DIR/tests/tools/pdf_links.py
python3 "$links" "$tmp/a/sheets.pdf" | grep -q . && fail "sheets.pdf has links"
if [ -e "$tmp/a/explore.html" ]; then
  gen --format svg,pdf --split --sheets 3 --seed 11 --out "$tmp/sl"
  python3 - "$links" "$tmp" <<'PY' || fail "the keys' links to explore.html"
import json, subprocess, sys
links, tmp = sys.argv[1], sys.argv[2]
def read(pdf):
    rows = [l.split() for l in subprocess.run(["python3", links, pdf], check=True, capture_output=True, text=True).stdout.splitlines()]
    return rows
ok = True
key = json.load(open(f"{tmp}/a/key.json"))
want = [f"explore.html#{s['id']}.{e['n']}" for s in key["sheets"] for e in s["exercises"]]
for name in ("a", "d"):
    rows = read(f"{tmp}/{name}/keys.pdf")
    got, pages = [r[1] for r in rows], [int(r[0]) for r in rows]
    if got != want:
        print(f"{name}/keys.pdf links {got}, expected {want}"); ok = False
    if not pages or pages[0] != 1 or pages != sorted(pages) or any(r[-1] != "in" for r in rows):
        print(f"{name}/keys.pdf links on pages {pages}, rectangles {[r[2:] for r in rows]}"); ok = False
for s in json.load(open(f"{tmp}/sl/key.json"))["sheets"]:
    got = [r[1] for r in read(f"{tmp}/sl/keys/{s['id']}.pdf")]
    if got != [f"../explore.html#{s['id']}.{e['n']}" for e in s["exercises"]]:
        print(f"keys/{s['id']}.pdf links {got}"); ok = False
sys.exit(0 if ok else 1)
PY
  for f in "$tmp"/sl/keys/*.pdf "$tmp"/sl/sheets/*.pdf; do
    qpdf --check "$f" >/dev/null || fail "qpdf --check ${f#$tmp/}"
  done
else
  python3 "$links" "$tmp/a/keys.pdf" | grep -q . && fail "keys.pdf has links, and the set no explore.html"
fi
# The bookmarks and the page labels (written by render/pdf_stream_writer, not cairo), read back
# with qpdf --json: one bookmark per sheet, in order, named by its id and opening its first page;
# its pages named "<id> 1/n" to "<id> n/n" in a viewer's page list, a duplex blank page "<id>".
python3 - "$tmp" <<'PY' || fail "the PDFs' bookmarks and page labels"
import json, re, subprocess, sys
tmp = sys.argv[1]
ids = [s["id"] for s in json.load(open(f"{tmp}/a/key.json"))["sheets"]]
ok = True
for name in ("a", "d"):
    for f in ("sheets", "keys"):
        j = json.loads(subprocess.run(["qpdf", "--json", "--json-key=outlines", "--json-key=pagelabels",
                                       "--json-key=pages", f"{tmp}/{name}/{f}.pdf"],
                                      check=True, capture_output=True, text=True).stdout)
        count = len(j["pages"])
        ranges = sorted((r["index"], r["label"]) for r in j["pagelabels"])
        def label(i):
            index, d = [r for r in ranges if r[0] <= i][-1]
            text = d.get("/P", "u:")[2:]
            return text + (str(d.get("/St", 1) + i - index) if "/S" in d else "")
        labels = [label(i) for i in range(count)]
        marks = [(o["title"], o["destpageposfrom1"]) for o in j["outlines"]]
        where = f"{name}/{f}.pdf"
        if [t for t, _ in marks] != ids:
            print(f"{where}: bookmarks {marks}, expected {ids}"); ok = False; continue
        starts = [p for _, p in marks] + [count + 1]
        for k, sheet in enumerate(ids):
            named = labels[starts[k] - 1:starts[k + 1] - 1]
            if named and named[-1] == sheet and name == "d":
                named = named[:-1]  # the blank page before the next sheet
            n = len(named)
            if named != [f"{sheet} {i}/{n}" for i in range(1, n + 1)] or n == 0:
                print(f"{where}: pages of {sheet} named {named}"); ok = False
sys.exit(0 if ok else 1)
PY
ls "$tmp/a" | grep -q '\.tmp$' && fail "a temporary file was left behind"

pages() { pdfinfo "$1" | awk '/^Pages:/ {print $2}'; }
ids=$(python3 -c 'import json,sys; print(" ".join(s["id"] for s in json.load(open(sys.argv[1]))["sheets"]))' "$tmp/a/key.json")
[ "$(echo $ids | wc -w)" -eq 6 ] || fail "key.json should list 6 sheets"

# Page counts: the SVG's pages, sheet by sheet in id order; with --duplex each sheet padded to
# an even count, so that the next one starts on an odd page.
for f in sheets keys; do
  total=0; padded=0
  for id in $ids; do
    n=$(grep -c 'class="page"' "$tmp/a/$f/$id.svg")
    [ "$n" -ge 1 ] || fail "$f/$id.svg has no page"
    total=$((total + n)); padded=$((padded + n + n % 2))
  done
  [ "$(pages "$tmp/a/$f.pdf")" -eq "$total" ] || fail "$f.pdf has $(pages "$tmp/a/$f.pdf") pages, the layout $total"
  [ "$(pages "$tmp/d/$f.pdf")" -eq "$padded" ] || fail "$f.pdf --duplex has $(pages "$tmp/d/$f.pdf") pages, not $padded"
done
# With --duplex, every sheet's first page ("page 1/n") is an odd page of the file.
first=1
for id in $ids; do
  n=$(grep -c 'class="page"' "$tmp/a/sheets/$id.svg")
  pdftotext -f $first -l $first "$tmp/d/sheets.pdf" - | grep -q "$id" || fail "duplex: page $first is not $id's first page"
  [ $((first % 2)) -eq 1 ] || fail "duplex: $id starts on an even page ($first)"
  first=$((first + n + n % 2))
done

# Text: every id, every page's "page i/n", the statements readable.
pdftotext "$tmp/a/sheets.pdf" "$tmp/sheets.txt" || fail "pdftotext sheets.pdf"
pdftotext "$tmp/a/keys.pdf" "$tmp/keys.txt" || fail "pdftotext keys.pdf"
for id in $ids; do
  grep -q "$id" "$tmp/sheets.txt" || fail "sheets.pdf lacks $id"
  grep -q "$id" "$tmp/keys.txt" || fail "keys.pdf lacks $id"
done
[ "$(grep -c '^page [0-9]*/[0-9]*$' "$tmp/sheets.txt")" -eq "$(pages "$tmp/a/sheets.pdf")" ] ||
  fail "not every page of sheets.pdf says 'page i/n'"
# (a phrase may be broken over two lines, in a column beside a figure: the text's lines joined)
tr '\n' ' ' < "$tmp/sheets.txt" > "$tmp/sheets-flat.txt"
for words in "Name:" "Student number:" "Exercise 1" "Using only the dot product" "orthogonal projection" \
              "Intersection of a ray and a circle" "Round every numerical answer to 2 decimals"; do
  grep -q "$words" "$tmp/sheets-flat.txt" || fail "sheets.pdf: no '$words' in pdftotext's output"
done
grep -q "Worked solution\|answer key" "$tmp/keys.txt" || fail "keys.pdf: no key wording"
grep -q "√" "$tmp/keys.txt" || fail "keys.pdf: no exact root (√) in the text"

# Fonts: embedded (and subset) only, DejaVu.
pdffonts "$tmp/a/sheets.pdf" | tail -n +3 > "$tmp/fonts.txt"
[ -s "$tmp/fonts.txt" ] || fail "pdffonts lists no font"
awk '$(NF-4) != "yes" {bad=1} END {exit bad}' "$tmp/fonts.txt" || fail "a font is not embedded: $(cat "$tmp/fonts.txt")"
grep -q DejaVuSans "$tmp/fonts.txt" || fail "not set in DejaVu Sans"

# Metadata.
info=$(pdfinfo "$tmp/a/sheets.pdf")
echo "$info" | grep -q '^Title: *Ray tracer 1.0' || fail "title: $info"
echo "$info" | grep -q '^Subject: *[A-Z]' || fail "no subject: $info"
echo "$info" | grep -q '^Creator: *epure ' || fail "no creator: $info"
echo "$info" | grep -q '^CreationDate: .*Nov 14 22:13:20 2023' || fail "creation date is not SOURCE_DATE_EPOCH: $info"
echo "$info" | grep -q '^Page size: *595.27.* x 841.8.* (A4)' || fail "not A4: $info"
# Without SOURCE_DATE_EPOCH: no date at all, and still the same bytes run after run.
(unset SOURCE_DATE_EPOCH
 gen --format pdf --sheets 2 --seed 11 --out "$tmp/n1"
 sleep 1
 gen --format pdf --sheets 2 --seed 11 --out "$tmp/n2"
 cmp -s "$tmp/n1/sheets.pdf" "$tmp/n2/sheets.pdf" || {
   # seen once under ASan with ctest -j2, not reproduced: say where the bytes differ
   cmp -l "$tmp/n1/sheets.pdf" "$tmp/n2/sheets.pdf" | head -5
   diff <(pdfinfo "$tmp/n1/sheets.pdf") <(pdfinfo "$tmp/n2/sheets.pdf")
   diff <(strings "$tmp/n1/sheets.pdf" | grep -a -E '/ID|Date|/Producer' ) <(strings "$tmp/n2/sheets.pdf" | grep -a -E '/ID|Date|/Producer')
   fail "without SOURCE_DATE_EPOCH, two runs differ"
 }
 pdfinfo "$tmp/n1/sheets.pdf" | grep -q CreationDate && fail "a date was written without SOURCE_DATE_EPOCH"
 exit 0) || exit 1
SOURCE_DATE_EPOCH=yesterday "$EPURE" generate --format pdf --sheets 1 --out "$tmp/bad" -q 2>"$tmp/err" &&
  fail "a bad SOURCE_DATE_EPOCH was accepted"
grep -q "SOURCE_DATE_EPOCH" "$tmp/err" || fail "the error does not name SOURCE_DATE_EPOCH: $(cat "$tmp/err")"

# French: accents and the decimal comma survive into the text layer.
gen --format pdf --sheets 1 --seed 11 --lang fr --out "$tmp/fr"
pdftotext "$tmp/fr/sheets.pdf" "$tmp/fr.txt"
grep -q "Numéro d'étudiant\|Numéro d’étudiant" "$tmp/fr.txt" || fail "French: no 'Numéro d'étudiant' in $(head -20 "$tmp/fr.txt")"
grep -q "é" "$tmp/fr.txt" || fail "French: accents lost"

# The QR code on every page of a sheet reads back as its page code (sheet id, page, page count,
# check), where layout.json says it is: the code's square and its quiet zone, cut out of the page
# at 150 dpi as a scan reads it (zbar, given a whole page, may take a corner mark for a finder
# pattern and give up).
first=1
for id in $(echo $ids | cut -d' ' -f1-2); do
  n=$(grep -c 'class="page"' "$tmp/a/sheets/$id.svg")
  for page in $(seq 1 "$n"); do
    crop=$(python3 -c "
import json, sys
l = json.load(open(sys.argv[1]))
s = next(s for s in l['sheets'] if s['sheet'] == sys.argv[2])
x, y, w, h = s['pages'][int(sys.argv[3]) - 1]['code']
k = 150 / 72
print(int((x - 8) * k), int((y - 8) * k), int((w + 16) * k), int((h + 16) * k))" "$tmp/a/layout.json" "$id" "$page")
    set -- $crop
    pdftoppm -r 150 -f $((first + page - 1)) -l $((first + page - 1)) -x "$1" -y "$2" -W "$3" -H "$4" -singlefile -png "$tmp/a/sheets.pdf" "$tmp/qr"
    read_back=$(zbarimg --quiet --raw "$tmp/qr.png" 2>/dev/null)
    case "$read_back" in
      "$id/$page/$n/"?) ;;
      *) fail "the QR code on $id's page $page reads '$read_back', not its page code $id/$page/$n/…" ;;
    esac
  done
  first=$((first + n))
done

# The two backends draw the same page: PDF page 1 against the SVG's first page, for a sheet and
# a key of two seeds; and the check can fail: another sheet's SVG must not pass. Tolerance: at
# 72 dpi, blurred 3x3, a mean difference of at most 4/255 and at most 0.15 % of the pixels off by
# more than 64 (measured: the same page 0.00-0.03 %, another sheet's first page 0.49 %).
set -- $ids
for f in sheets keys; do
  pdftoppm -r 72 -f 1 -l 1 -singlefile -png "$tmp/a/$f.pdf" "$tmp/pdf_$f"
  rsvg-convert -d 72 -p 72 "$tmp/a/$f/$1.svg" -o "$tmp/svg_$f.png" || fail "rsvg-convert $f/$1.svg"
  python3 "$compare" "$tmp/pdf_$f.png" "$tmp/svg_$f.png" --max-mean 4 --max-bad 0.0015 ||
    fail "$f: the PDF and SVG pages of $1 differ"
done
rsvg-convert -d 72 -p 72 "$tmp/a/sheets/$2.svg" -o "$tmp/other.png"
python3 "$compare" "$tmp/pdf_sheets.png" "$tmp/other.png" --max-mean 4 --max-bad 0.0015 >/dev/null &&
  fail "the pixel comparison cannot tell two different sheets apart"
gen --format svg,pdf --sheets 1 --seed 3 --difficulty hard --out "$tmp/h"
hid=$(ls "$tmp/h/sheets" | sed 's/\.svg$//')
pdftoppm -r 72 -f 1 -l 1 -singlefile -png "$tmp/h/keys.pdf" "$tmp/h_pdf"
rsvg-convert -d 72 -p 72 "$tmp/h/keys/$hid.svg" -o "$tmp/h_svg.png"
python3 "$compare" "$tmp/h_pdf.png" "$tmp/h_svg.png" --max-mean 4 --max-bad 0.0015 || fail "hard key: PDF and SVG differ"

# --split: one PDF per sheet and per key, each complete.
gen --format pdf --split --sheets 3 --seed 11 --out "$tmp/s"
[ "$(ls "$tmp/s/sheets"/*.pdf | wc -l)" -eq 3 ] || fail "--split: expected 3 sheet PDFs"
[ "$(ls "$tmp/s/keys"/*.pdf | wc -l)" -eq 3 ] || fail "--split: expected 3 key PDFs"
[ -e "$tmp/s/sheets.pdf" ] && fail "--split also wrote the class set"
for id in $(echo $ids | cut -d' ' -f1-3); do
  qpdf --check "$tmp/s/sheets/$id.pdf" >/dev/null || fail "qpdf --check sheets/$id.pdf"
  qpdf --check "$tmp/s/keys/$id.pdf" >/dev/null || fail "qpdf --check keys/$id.pdf"
  [ "$(pages "$tmp/s/sheets/$id.pdf")" -eq "$(grep -c 'class="page"' "$tmp/a/sheets/$id.svg")" ] || fail "sheets/$id.pdf page count"
done

# --paper letter.
gen --format pdf --sheets 1 --paper letter --out "$tmp/l"
pdfinfo "$tmp/l/sheets.pdf" | grep -q '^Page size: *612 x 792' || fail "--paper letter: $(pdfinfo "$tmp/l/sheets.pdf" | grep size)"
[ -e "$tmp/l/sheets" ] && fail "--format pdf wrote SVG directories"

# epure preview: the question's and the key's diagrams as PNG.
"$EPURE" preview ray_circle --branch hit --out "$tmp/p" >/dev/null || fail "preview ray_circle"
for f in ray_circle-question.png ray_circle-key.png; do
  [ "$(head -c 8 "$tmp/p/$f" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "preview: $f is not a PNG"
done
"$EPURE" preview ray_ellipse --out "$tmp/p" >/dev/null || fail "preview ray_ellipse"
"$EPURE" preview nonsense --out "$tmp/p" 2>"$tmp/err" && fail "preview accepted an unknown kind"
grep -q "unknown kind 'nonsense'" "$tmp/err" || fail "preview: $(cat "$tmp/err")"
"$EPURE" preview ray_circle --branch sideways --out "$tmp/p" 2>"$tmp/err" && fail "preview accepted an unknown branch"
grep -q "no branch 'sideways'" "$tmp/err" || fail "preview: $(cat "$tmp/err")"
echo "ok: pdf"
