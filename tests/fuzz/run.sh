#!/usr/bin/env bash
# The fuzz targets of tests/fuzz (README.md beside this file).
#   bash tests/fuzz/run.sh [SECONDS]      every target for SECONDS (default 60), all at once under
#                                         nice -n 19, each from its seed corpus; new inputs go to
#                                         $BUILD/work/<target>/, crashes to $BUILD/work/<target>-crash-*
#   bash tests/fuzz/run.sh --smoke TARGET one target over its corpus (every kept crash among it),
#                                         then EPURE_FUZZ_SMOKE_SECONDS (default 4) of fuzzing (ctest)
# $EPURE_FUZZ_BUILD is the fuzz build directory (default build-fuzz), configured with
#   cmake -S . -B build-fuzz -DEPURE_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo
# EPURE_FUZZ_FORK=1 runs each target in libFuzzer's fork mode with -ignore_crashes=1 (a long run
# that goes on past a crash and keeps them all).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${EPURE_FUZZ_BUILD:-$root/build-fuzz}
targets=(solve spec key answers_csv answers_json expression sheet_id submission sheet_tag harness_protocol corrections roster scan_image scan_layout scan_crop)
# bounds for every run: a hang is a crash after 10 s, an input that needs 2 GiB one too
common=(-timeout=10 -rss_limit_mb=2048 -print_final_stats=1)

if [ "${1:-}" = "--smoke" ]; then
  t=${2:?usage: run.sh --smoke TARGET}
  bin=$build/fuzz_$t
  if [ ! -x "$bin" ]; then
    echo "SKIPPED: $bin is not built (clang's fuzzer runtime missing? install clang, libfuzzer-14-dev, libclang-rt-14-dev)"
    exit 77
  fi
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  mkdir "$tmp/corpus"
  # the committed corpus is read, never written: new inputs go to a scratch directory
  if ! "$bin" "${common[@]}" -max_total_time="${EPURE_FUZZ_SMOKE_SECONDS:-4}" -artifact_prefix="$tmp/" \
      "$tmp/corpus" "$here/corpus/$t" >"$tmp/log" 2>&1; then
    tail -n 60 "$tmp/log"
    for c in "$tmp"/crash-* "$tmp"/timeout-* "$tmp"/oom-* "$tmp"/leak-*; do
      [ -e "$c" ] && echo "fuzz.$t: input that fails (base64): $(head -c 3000 "$c" | base64 -w0)"
    done
    exit 1
  fi
  grep -aE "^#[0-9]+[[:space:]]+(INITED|DONE)" "$tmp/log" | sed "s/^/fuzz.$t: /" || true
  grep -aE "stat::number_of_executed_units" "$tmp/log" | sed "s/^/fuzz.$t: /" || true
  exit 0
fi

seconds=${1:-60}
work=$build/work
mkdir -p "$work"
pids=()
for t in "${targets[@]}"; do
  bin=$build/fuzz_$t
  [ -x "$bin" ] || { echo "run.sh: $bin is not built" >&2; exit 2; }
  mkdir -p "$work/$t"
  mode=()
  [ "${EPURE_FUZZ_FORK:-0}" = 1 ] && mode=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  nice -n 19 "$bin" "${common[@]}" "${mode[@]}" -max_total_time="$seconds" -artifact_prefix="$work/$t-" \
    "$work/$t" "$here/corpus/$t" >"$work/$t.log" 2>&1 &
  pids+=($!)
done
status=0
for i in "${!targets[@]}"; do
  t=${targets[$i]}
  if ! wait "${pids[$i]}"; then status=1; fi
  last=$(grep -aE "^#[0-9]+" "$work/$t.log" | tail -n 1 || true)
  crashes=$(ls "$work/$t"-crash-* "$work/$t"-timeout-* "$work/$t"-oom-* 2>/dev/null | wc -l)
  echo "$t: $last; files found: $crashes (log: $work/$t.log)"
done
exit $status
