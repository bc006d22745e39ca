#!/usr/bin/env bash
# `epure generate --format svg` against the floor (issue 4, issue 34's measure): the bare C
# program of ../shared/bench-floor/ in `svg` mode (fprintf of a sheet page and a key page, two
# files a sheet) and epure writing sheets/<id>.svg, keys/<id>.svg and key.json for the same
# number of sheets, in the same run, each pinned to one core (taskset), the two alternated run by
# run. Both are measured in CPU time, user + system (bench/cpu_time.py: the kernel's
# microseconds, not GNU time's centiseconds, which read the floor's 0.05-0.08 s to about ±20 %),
# not wall time: the machine is shared, and the floor's wall time is mostly waiting for the file
# system. Prints each run, the medians, and the ratio the target is stated in: epure's CPU time
# a page over the floor's (target <= 2.0x).
#
#   bench/svg_bench.sh [BUILD_DIR] [SHEETS] [RUNS] [SPEC]    e.g. bench/svg_bench.sh build 1000 5
# SPEC defaults to the built-in course worksheet; bench/floor_like.toml holds the floor's four
# exercises (projection, segments, ray/circle, ray/square) for a like-for-like comparison.
# EPURE=path measures another binary; CPU=n pins to core n (default 1).
set -eu
build=${1:-build}
sheets=${2:-1000}
runs=${3:-5}
spec=${4:-}
cpu=${CPU:-1}
epure=${EPURE:-$build/epure}
shared=${EPURE_SHARED_DIR:-$(dirname "$0")/../../shared}
work=${BENCH_DIR:-$(mktemp -d)}
bench=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
trap '[ -z "${BENCH_DIR:-}" ] && rm -rf "$work"' EXIT

cc -O2 -std=gnu11 -o "$work/floor" "$shared/bench-floor/sheets.c" \
  $(pkg-config --cflags --libs cairo cairo-pdf pangocairo librsvg-2.0) -lm

spec_args=()
[ -n "$spec" ] && spec_args=(--spec "$spec")
once() {  # once LABEL OUTDIR COMMAND...: appends "user sys" of one run to LABEL.cpu
  local label=$1 out=$2; shift 2
  rm -rf "$out" && mkdir -p "$out"
  python3 "$bench/cpu_time.py" "%U %S" "$work/time" "$@"
  cat "$work/time" >> "$work/$label.cpu"
}
: > "$work/floor.cpu"; : > "$work/epure.cpu"
for r in $(seq "$runs"); do
  once floor "$work/floor-svg" taskset -c "$cpu" "$work/floor" svg "$sheets" "$work/floor-svg"
  once epure "$work/epure" taskset -c "$cpu" "$epure" generate "${spec_args[@]}" --format svg \
    --sheets "$sheets" --jobs 1 --quiet --out "$work/epure"
done

# pages: the floor writes one page a file; epure's SVGs stack a document's pages, one
# class="page" group each
fp=$(find "$work/floor-svg" -name '*.svg' | wc -l)
ep=$(cat "$work/epure"/sheets/*.svg "$work/epure"/keys/*.svg | grep -o 'class="page"' | wc -l)
python3 - "$sheets" "$fp" "$ep" "${spec:-built-in course}" "$work/floor.cpu" "$work/epure.cpu" <<'PY'
import statistics, sys
n, fp, ep = map(int, sys.argv[1:4])
read = lambda path: [tuple(map(float, l.split())) for l in open(path) if l.strip()]
floor, epure = read(sys.argv[5]), read(sys.argv[6])
print(f"{n} sheets, spec: {sys.argv[4]}; floor {fp} pages, epure {ep} pages ({ep / n:.2f} a sheet)")
print("| run | floor user+sys (s) | epure user+sys (s) | floor ms a page | epure ms a page | ratio a page |")
print("|---:|---:|---:|---:|---:|---:|")
ratios = []
for i, ((fu, fs), (eu, es)) in enumerate(zip(floor, epure), 1):
    f, e = fu + fs, eu + es
    fpp, epp = 1000 * f / fp, 1000 * e / ep
    ratios.append(epp / fpp if fpp > 0 else float("inf"))
    print(f"| {i} | {fu:.3f}+{fs:.3f} | {eu:.3f}+{es:.3f} | {fpp:.4f} | {epp:.4f} | {ratios[-1]:.2f}x |")
f = statistics.median(u + s for u, s in floor)
e = statistics.median(u + s for u, s in epure)
print(f"median CPU: floor {1000 * f / fp:.4f} ms a page, epure {1000 * e / ep:.4f} ms a page: "
      f"{(e / ep) / (f / fp):.2f}x the floor's CPU time a page (target <= 2.0x); "
      f"run by run {min(ratios):.2f}x to {max(ratios):.2f}x")
PY
