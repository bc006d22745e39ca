#!/usr/bin/env bash
# `epure generate --format pdf` against the floor (issue 5): the bare C program of
# ../shared/bench-floor/ in `pango` mode (two pages a sheet drawn with cairo + pango, no layout)
# and epure writing the class-set PDFs (sheets.pdf + keys.pdf, generation included), for the same
# number of sheets, in the same run, on one core (taskset) and then epure with two jobs on both
# cores. Prints the median of RUNS runs: wall and user CPU (GNU time), per sheet and per page,
# and the ratios the targets are stated in.
#
#   bench/pdf_bench.sh [BUILD_DIR] [SHEETS] [RUNS] [SPEC]  e.g. bench/pdf_bench.sh build 500 3
# SPEC defaults to the built-in course worksheet; bench/floor_like.toml holds the floor's four
# exercises (projection, segments, ray/circle, ray/square) for a like-for-like comparison.
set -eu
build=${1:-build}
sheets=${2:-500}
runs=${3:-3}
spec=${4:-}
spec_args=()
[ -n "$spec" ] && spec_args=(--spec "$spec")
epure=${EPURE:-$build/epure}
shared=${EPURE_SHARED_DIR:-$(dirname "$0")/../../shared}
work=${BENCH_DIR:-$(mktemp -d)}
mkdir -p "$work"
trap '[ -z "${BENCH_DIR:-}" ] && rm -rf "$work"' EXIT
export SOURCE_DATE_EPOCH=1700000000

cc -O2 -std=gnu11 -o "$work/floor" "$shared/bench-floor/sheets.c" \
  $(pkg-config --cflags --libs cairo cairo-pdf pangocairo librsvg-2.0) -lm

# median of the runs' "wall user" pairs, by wall
measure() {  # measure LABEL COMMAND...
  local label=$1; shift
  for r in $(seq "$runs"); do
    /usr/bin/time -f "%e %U" -o "$work/time.$r" "$@" >/dev/null
  done
  cat "$work"/time.* | sort -n | sed -n "$(( (runs + 1) / 2 ))p" > "$work/$label.median"
  rm -f "$work"/time.*
}

measure floor taskset -c 0 "$work/floor" pango "$sheets" "$work/floor.pdf"
measure one taskset -c 0 "$epure" generate "${spec_args[@]}" --format pdf --sheets "$sheets" --jobs 1 --quiet --out "$work/one"
measure two "$epure" generate "${spec_args[@]}" --format pdf --sheets "$sheets" --jobs 2 --quiet --out "$work/two"
cmp -s "$work/one/sheets.pdf" "$work/two/sheets.pdf" && cmp -s "$work/one/keys.pdf" "$work/two/keys.pdf" ||
  { echo "FAIL: --jobs 1 and --jobs 2 PDFs differ"; exit 1; }

floor_pages=$(pdfinfo "$work/floor.pdf" | awk '/^Pages:/ {print $2}')
pages=$(( $(pdfinfo "$work/one/sheets.pdf" | awk '/^Pages:/ {print $2}') + $(pdfinfo "$work/one/keys.pdf" | awk '/^Pages:/ {print $2}') ))
read -r fw fu < "$work/floor.median"
read -r ow ou < "$work/one.median"
read -r tw tu < "$work/two.median"
python3 - "$sheets" "$floor_pages" "$pages" "$fw" "$fu" "$ow" "$ou" "$tw" "$tu" "${spec:-built-in course}" <<'PY'
import sys
n, fp, ep = map(int, sys.argv[1:4])
fw, fu, ow, ou, tw, tu = map(float, sys.argv[4:10])
print(f"{n} sheets, spec: {sys.argv[10]}; floor: {fp} pages, epure: {ep} pages ({ep / n:.1f} a sheet)")
print(f"| program | wall | user CPU | per sheet (wall) | per page (wall) |")
print(f"|---|---|---|---|---|")
for name, w, u, p in (("floor `pango`, one core", fw, fu, fp), ("epure --jobs 1, one core", ow, ou, ep),
                      ("epure --jobs 2, two cores", tw, tu, ep)):
    print(f"| {name} | {w:.2f} s | {u:.2f} s | {1000 * w / n:.2f} ms | {1000 * w / p:.3f} ms |")
print(f"ratio one core: {ow / fw:.2f}x the floor (target <= 1.5x); "
      f"two jobs: {tw / fw:.2f}x the floor's one-core time (target <= 0.85x)")
print(f"per page: {(ow / ep) / (fw / fp):.2f}x the floor's time per page")
PY
