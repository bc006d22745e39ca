#!/usr/bin/env bash
# `epure generate --format pdf` against the floor (issue 5, issue 34's measure): the bare C
# program of ../shared/bench-floor/ in `pango` mode (two pages a sheet drawn with cairo + pango,
# no layout) and epure writing the class-set PDFs (sheets.pdf + keys.pdf, generation included),
# for the same number of sheets, in the same run, run by run alternated:
# - one core: the floor and `epure --jobs 1`, each pinned to one core (taskset), in CPU time,
#   user + system (bench/cpu_time.py, in microseconds): target <= 1.3x the floor's CPU time a page;
# - two jobs: `epure --jobs 2` on both cores, its wall time (what two cores buy is time, not CPU)
#   against the floor's one-core CPU time a page: target <= 0.75x. Its CPU time is printed too.
# The machine is shared: run it where nothing else runs, or read the spread between runs.
#
#   bench/pdf_bench.sh [BUILD_DIR] [SHEETS] [RUNS] [SPEC]  e.g. bench/pdf_bench.sh build 300 5
# SPEC defaults to the built-in course worksheet; bench/floor_like.toml holds the floor's four
# exercises (projection, segments, ray/circle, ray/square) for a like-for-like comparison.
# EPURE=path measures another binary; CPU=n pins the one-core runs to core n (default 1).
set -eu
build=${1:-build}
sheets=${2:-300}
runs=${3:-5}
spec=${4:-}
cpu=${CPU:-1}
spec_args=()
[ -n "$spec" ] && spec_args=(--spec "$spec")
epure=${EPURE:-$build/epure}
shared=${EPURE_SHARED_DIR:-$(dirname "$0")/../../shared}
work=${BENCH_DIR:-$(mktemp -d)}
bench=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
trap '[ -z "${BENCH_DIR:-}" ] && rm -rf "$work"' EXIT
export SOURCE_DATE_EPOCH=1700000000

cc -O2 -std=gnu11 -o "$work/floor" "$shared/bench-floor/sheets.c" \
  $(pkg-config --cflags --libs cairo cairo-pdf pangocairo librsvg-2.0) -lm

once() {  # once LABEL COMMAND...: appends "wall user sys" of one run to LABEL.times
  local label=$1; shift
  python3 "$bench/cpu_time.py" "%e %U %S" "$work/time" "$@"
  cat "$work/time" >> "$work/$label.times"
}
: > "$work/floor.times"; : > "$work/one.times"; : > "$work/two.times"
for r in $(seq "$runs"); do
  once floor taskset -c "$cpu" "$work/floor" pango "$sheets" "$work/floor.pdf"
  rm -rf "$work/one"
  once one taskset -c "$cpu" "$epure" generate "${spec_args[@]}" --format pdf --sheets "$sheets" --jobs 1 --quiet --out "$work/one"
  rm -rf "$work/two"
  once two "$epure" generate "${spec_args[@]}" --format pdf --sheets "$sheets" --jobs 2 --quiet --out "$work/two"
done
cmp -s "$work/one/sheets.pdf" "$work/two/sheets.pdf" && cmp -s "$work/one/keys.pdf" "$work/two/keys.pdf" ||
  { echo "FAIL: --jobs 1 and --jobs 2 PDFs differ"; exit 1; }

floor_pages=$(pdfinfo "$work/floor.pdf" | awk '/^Pages:/ {print $2}')
pages=$(( $(pdfinfo "$work/one/sheets.pdf" | awk '/^Pages:/ {print $2}') + $(pdfinfo "$work/one/keys.pdf" | awk '/^Pages:/ {print $2}') ))
python3 - "$sheets" "$floor_pages" "$pages" "${spec:-built-in course}" "$work/floor.times" "$work/one.times" "$work/two.times" <<'PY'
import statistics, sys
n, fp, ep = map(int, sys.argv[1:4])
read = lambda path: [tuple(map(float, l.split())) for l in open(path) if l.strip()]
floor, one, two = (read(p) for p in sys.argv[5:8])
print(f"{n} sheets, spec: {sys.argv[4]}; floor: {fp} pages, epure: {ep} pages ({ep / n:.2f} a sheet)")
print("| run | floor CPU ms a page | epure --jobs 1 CPU ms a page | one-core ratio | --jobs 2 wall ms a page (CPU) | two-job ratio |")
print("|---:|---:|---:|---:|---:|---:|")
r1, r2 = [], []
for i, (f, o, t) in enumerate(zip(floor, one, two), 1):
    fc = 1000 * (f[1] + f[2]) / fp
    oc = 1000 * (o[1] + o[2]) / ep
    tw, tc = 1000 * t[0] / ep, 1000 * (t[1] + t[2]) / ep
    r1.append(oc / fc); r2.append(tw / fc)
    print(f"| {i} | {fc:.3f} | {oc:.3f} | {r1[-1]:.2f}x | {tw:.3f} ({tc:.3f}) | {r2[-1]:.2f}x |")
print(f"median: one core {statistics.median(r1):.2f}x the floor's CPU time a page (target <= 1.3x), "
      f"runs {min(r1):.2f}-{max(r1):.2f}x; two jobs {statistics.median(r2):.2f}x (wall, target <= 0.75x), "
      f"runs {min(r2):.2f}-{max(r2):.2f}x")
PY
