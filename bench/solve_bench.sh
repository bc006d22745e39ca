#!/usr/bin/env bash
# `epure solve` end to end on one core: lines per second on a fixed mixed file, JSON parsing and
# writing included. usage: bench/solve_bench.sh BUILD_DIR [LINES=1000000] [RUNS=7] [CPU=1]
# Prints each run and the median. The file comes from solve_input (solve_lines.h): the same
# bytes on every machine for the same LINES. EPURE=path times another epure binary.
set -euo pipefail
build=${1:?usage: solve_bench.sh BUILD_DIR [LINES] [RUNS] [CPU]}
lines=${2:-1000000}
runs=${3:-7}
cpu=${4:-1}
epure=${EPURE:-$build/epure}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$build/solve_input" "$lines" >"$tmp/in.jsonl"
pin=()
command -v taskset >/dev/null && pin=(taskset -c "$cpu")

# A first run checks the output (every line solved) and warms the page cache.
"${pin[@]}" "$epure" solve "$tmp/in.jsonl" >"$tmp/out.jsonl"
[ "$(wc -l <"$tmp/out.jsonl")" -eq "$lines" ] || { echo "output has the wrong number of lines"; exit 1; }

echo "epure solve: $lines lines ($(du -h "$tmp/in.jsonl" | cut -f1)), ${pin[*]:-not pinned}"
rates=()
for ((i = 1; i <= runs; i++)); do
  start=$(date +%s.%N)
  "${pin[@]}" "$epure" solve "$tmp/in.jsonl" >/dev/null
  end=$(date +%s.%N)
  seconds=$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')
  rate=$(awk -v n="$lines" -v s="$seconds" 'BEGIN { print n / s }')
  printf 'run %d: %.3f s, %.0f lines/s\n' "$i" "$seconds" "$rate"
  rates+=("$rate")
done
median=$(printf '%s\n' "${rates[@]}" | sort -g | awk '{ r[NR] = $1 } END { print (NR % 2) ? r[(NR + 1) / 2] : (r[NR / 2] + r[NR / 2 + 1]) / 2 }')
printf 'median: %.0f lines/s (target: 500000)\n' "$median"
