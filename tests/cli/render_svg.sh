#!/usr/bin/env bash
# The SVG backend end to end: sample scenes of every kind of figure (epure_render_demo, built
# beside `epure`) are well-formed XML (xmllint), render (rsvg-convert), are byte-identical across
# two runs, and have every label placed cleanly.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
demo=${EPURE_RENDER_DEMO:-$(dirname "$EPURE")/epure_render_demo}
[ -x "$demo" ] || fail "no $demo (build the epure_render_demo target)"
command -v xmllint >/dev/null || fail "xmllint missing (libxml2-utils)"
command -v rsvg-convert >/dev/null || fail "rsvg-convert missing (librsvg2-bin)"

"$demo" "$tmp/a" >"$tmp/a.log" || { cat "$tmp/a.log"; fail "a label could not be placed cleanly"; }
"$demo" "$tmp/b" >/dev/null || fail "second run"
diff -r "$tmp/a" "$tmp/b" >/dev/null || fail "two runs differ"
n=0
for svg in "$tmp"/a/*.svg; do
  xmllint --noout "$svg" || fail "$(basename "$svg") is not well-formed"
  rsvg-convert "$svg" -o "${svg%.svg}.png" || fail "$(basename "$svg") does not render"
  [ -s "${svg%.svg}.png" ] || fail "$(basename "$svg") rendered empty"
  grep -q '<title>' "$svg" || fail "$(basename "$svg") has no <title>"
  grep -q 'viewBox=' "$svg" || fail "$(basename "$svg") has no viewBox"
  n=$((n + 1))
done
[ "$n" -ge 6 ] || fail "expected at least 6 sample scenes, got $n"
echo "ok: $n scenes"
