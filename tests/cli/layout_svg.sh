#!/usr/bin/env bash
# Laid-out pages end to end: the sample worksheet and key of epure_layout_demo (built beside
# `epure`) are well-formed XML (xmllint), render to PNG (rsvg-convert) at the stacked pages' size,
# and are byte-identical across two runs.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
demo=${EPURE_LAYOUT_DEMO:-$(dirname "$EPURE")/epure_layout_demo}
[ -x "$demo" ] || fail "no $demo (build the epure_layout_demo target)"
command -v xmllint >/dev/null || fail "xmllint missing (libxml2-utils)"
command -v rsvg-convert >/dev/null || fail "rsvg-convert missing (librsvg2-bin)"

"$demo" "$tmp/a" || fail "first run"
"$demo" "$tmp/b" || fail "second run"
diff -r "$tmp/a" "$tmp/b" >/dev/null || fail "two runs differ"
for name in sheet key; do
  svg=$tmp/a/$name.svg
  xmllint --noout "$svg" || fail "$name.svg is not well-formed"
  rsvg-convert -d 72 -p 72 "$svg" -o "$tmp/$name.png" || fail "$name.svg does not render"
  pages=$(grep -c 'class="page"' "$svg")
  [ "$pages" -ge 1 ] || fail "$name.svg has no page"
  # A4 at 72 dpi is 596 × 842 px; the pages are stacked 8 pt apart.
  want_h=$(( pages * 842 + (pages - 1) * 8 ))
  size=$(file "$tmp/$name.png" | grep -o '[0-9]* x [0-9]*')
  w=${size%% x *}; h=${size##* x }
  [ "$w" -ge 595 ] && [ "$w" -le 596 ] || fail "$name.png is $w px wide"
  [ $(( h - want_h )) -ge -1 ] && [ $(( h - want_h )) -le 1 ] || fail "$name.png is $h px high, not $want_h"
  grep -q '<title>' "$svg" || fail "$name.svg has no <title>"
  grep -q '<desc>' "$svg" || fail "$name.svg has no <desc>"
  grep -q 'xml:lang="fr"' "$svg" || fail "$name.svg has no language"
done
grep -q 'class="page"' "$tmp/a/sheet.svg" && [ "$(grep -c 'class="page"' "$tmp/a/sheet.svg")" -ge 2 ] ||
  fail "the sample sheet should flow onto a second page"
echo "ok: sheet and key"
