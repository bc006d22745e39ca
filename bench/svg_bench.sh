#!/usr/bin/env bash
# `epure generate --format svg` against the floor (issue 4): the bare C program of
# ../shared/bench-floor/ in `svg` mode (fprintf of a sheet page and a key page, two files a sheet)
# and epure writing sheets/<id>.svg, keys/<id>.svg and key.json for the same number of sheets, in
# the same run, both pinned to one core (taskset). Prints the median of RUNS runs (wall and user
# CPU, GNU time), bytes written, and the ratio the target is stated in (time / floor's time).
#
#   bench/svg_bench.sh [BUILD_DIR] [SHEETS] [RUNS] [SPEC]    e.g. bench/svg_bench.sh build 1000 5
# SPEC defaults to the built-in course worksheet; bench/floor_like.toml holds the floor's four
# exercises (projection, segments, ray/circle, ray/square) for a like-for-like comparison.
set -eu
build=${1:-build}
sheets=${2:-1000}
runs=${3:-5}
spec=${4:-}
cpu=${CPU:-1}
epure=${EPURE:-$build/epure}
shared=${EPURE_SHARED_DIR:-$(dirname "$0")/../../shared}
work=${BENCH_DIR:-$(mktemp -d)}
mkdir -p "$work"
trap '[ -z "${BENCH_DIR:-}" ] && rm -rf "$work"' EXIT

cc -O2 -std=gnu11 -o "$work/floor" "$shared/bench-floor/sheets.c" \
  $(pkg-config --cflags --libs cairo cairo-pdf pangocairo librsvg-2.0) -lm

measure() {  # measure LABEL OUTDIR COMMAND...: median of the runs' "wall user", by wall
  local label=$1 out=$2; shift 2
  for r in $(seq "$runs"); do
    rm -rf "$out" && mkdir -p "$out"
    /usr/bin/time -f "%e %U" -o "$work/time.$r" "$@" >/dev/null
  done
  cat "$work"/time.* | sort -n | sed -n "$(( (runs + 1) / 2 ))p" > "$work/$label.median"
  rm -f "$work"/time.*
}

spec_args=()
[ -n "$spec" ] && spec_args=(--spec "$spec")
measure floor "$work/floor-svg" taskset -c "$cpu" "$work/floor" svg "$sheets" "$work/floor-svg"
measure epure "$work/epure" taskset -c "$cpu" "$epure" generate "${spec_args[@]}" --format svg \
  --sheets "$sheets" --jobs 1 --quiet --out "$work/epure"

# pages: the floor writes one page a file; epure's SVGs stack a document's pages, one
# class="page" group each
fp=$(find "$work/floor-svg" -name '*.svg' | wc -l)
ep=$(cat "$work/epure"/sheets/*.svg "$work/epure"/keys/*.svg | grep -o 'class="page"' | wc -l)
fb=$(du -sb "$work/floor-svg" | cut -f1)
eb=$(du -sb "$work/epure" | cut -f1)
read -r fw fu < "$work/floor.median"
read -r ew eu < "$work/epure.median"
python3 - "$sheets" "$fb" "$eb" "$fw" "$fu" "$ew" "$eu" "${spec:-built-in course}" "$fp" "$ep" <<'PY'
import sys
n, fb, eb = map(int, sys.argv[1:4])
fw, fu, ew, eu = map(float, sys.argv[4:8])
fp, ep = map(int, sys.argv[9:11])
print(f"{n} sheets, spec: {sys.argv[8]}; floor writes {fb / n / 1024:.1f} KiB a sheet, epure {eb / n / 1024:.1f} KiB")
print("| program | wall | user CPU | per sheet (wall) |")
print("|---|---|---|---|")
for name, w, u in (("floor `svg`", fw, fu), ("epure --format svg --jobs 1", ew, eu)):
    print(f"| {name} | {w:.2f} s | {u:.2f} s | {1000 * w / n:.2f} ms |")
print(f"ratio: {ew / fw:.2f}x the floor's wall time (target <= 1.8x), {eu / max(fu, 0.01):.1f}x its user CPU; "
      f"per KiB written: {(ew / eb) / (fw / fb):.2f}x")
print(f"per page: floor {fp} pages, {1000 * fw / fp:.3f} ms a page; epure {ep} pages ({ep / n:.1f} a sheet), "
      f"{1000 * ew / ep:.3f} ms a page; {(ew / ep) / (fw / fp):.2f}x the floor's time per page (target <= 2.0x)")
PY
