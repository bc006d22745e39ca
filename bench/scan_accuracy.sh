#!/usr/bin/env bash
# The scan's reading figures on four stacks of SHEETS French sheets (default 24), made as
# tests/cli/scan.sh makes its small ones (same formats, degradations and seeds 41-44: a copier's
# 200 dpi JPEG PDF with mess, a bilevel CCITT G4 TIFF at 200 dpi, a 300 dpi Flate PDF, 150 dpi
# PNGs), held-out digits written by tests/scan/scan_fixture.h. Prints each stack's figures and the
# total, and where the comb errors and reviews come from (bench/scan_errors.py).
#
#   bash bench/scan_accuracy.sh BUILD_DIR [SHEETS] [WORK_DIR]
#
# WORK_DIR keeps the stacks (made once, reused when present: to compare two binaries on the same
# scans, run with the same WORK_DIR; EPURE=path overrides BUILD_DIR/epure for the scan).
# SET_SEED (default 5) and STACK_SEED (default 40: the stacks' seeds are 41-44) make other stacks:
# a second sample of the same kind, to confirm on scans a choice was not made on. ROSTER=N makes
# the set as the README's workflow does, `generate --roster` of N students (numbers and names
# made here from the set's seed), so that no student number is written: its sheets are the
# roster's, SHEETS is then N.
set -eu
build=$(cd "$1" && pwd); sheets=${2:-24}; work=${3:-$(mktemp -d)}
set_seed=${SET_SEED:-5}; stack_seed=${STACK_SEED:-40}
src=$(cd "$(dirname "$0")/.." && pwd)
epure=${EPURE:-$build/epure}
mkdir -p "$work"
if [ ! -f "$work/set/key.json" ]; then
  if [ -n "${ROSTER:-}" ]; then
    sheets=$ROSTER
    python3 - "$ROSTER" "$set_seed" >"$work/roster.csv" <<'PY'
import random, sys
n, seed = int(sys.argv[1]), int(sys.argv[2])
r = random.Random(seed)
print("number;name;email")
for i in range(n):
    print(f"{r.randrange(10**7, 10**8)};Élève {i + 1:02d};")
PY
    "$build/epure" generate --format pdf --roster "$work/roster.csv" --seed "$set_seed" --lang fr --jobs 2 --quiet --out "$work/set"
  else
    "$build/epure" generate --format pdf --sheets "$sheets" --seed "$set_seed" --lang fr --jobs 2 --quiet --out "$work/set"
  fi
fi
[ -f "$work/roster.csv" ] && sheets=$(($(wc -l <"$work/roster.csv") - 1))
i=0
for spec in "pdf copier 200 --mess" "tiff-g4 bilevel 200" "pdf-flate copier 300" "png copier 150"; do
  set -- $spec
  i=$((i + 1))
  d=$work/s$i
  if [ ! -f "$d/truth.json" ]; then
    "$build/epure_scan_fixture" --key "$work/set/key.json" --set "$work/set" --out "$d" --sheets "$sheets" \
      --format "$1" --degrade "$2" --dpi "$3" --seed $((stack_seed + i)) ${4:-} >/dev/null
  fi
  rm -rf "$d/out"
  "$epure" scan "$d"/scan* --key "$work/set/key.json" --layout "$d/layout.json" --out "$d/out" --jobs 2 -q 2>"$d/err" || [ $? = 1 ]
  python3 "$src/tests/tools/scan_figures.py" "$d/truth.json" "$d/out" "$d/layout.json" >"$d/figures.json"
done
python3 "$src/bench/scan_errors.py" "$work"/s1 "$work"/s2 "$work"/s3 "$work"/s4
