#!/usr/bin/env bash
# epure scan's speed and memory (bench/README.md, "Scan"): a 200 dpi grey PDF of a French class
# (the suite's own scans, tests/scan/scan_fixture.h: one JPEG image a page, as a copier writes)
# read with two jobs; its pages given PASSES times over (every copy is read in full: the later
# ones are then duplicates) to see memory over 1,000 pages; with a fourth argument `crops`, read
# with --crops (every field's crop written).
#   bash bench/scan_bench.sh BUILD_DIR [SHEETS] [PASSES] [crops]
# Prints pages, wall time, CPU time (user + sys), pages per second of wall and of CPU, and the
# peak resident memory.
set -euo pipefail
build=${1:?usage: scan_bench.sh BUILD_DIR [SHEETS] [PASSES] [crops]}
sheets=${2:-30}
passes=${3:-10}
crops=()
[ "${4:-}" = crops ] && crops=(--crops)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$build/epure" generate --format pdf --sheets "$sheets" --seed 5 --lang fr --quiet --out "$tmp/set"
"$build/epure_scan_fixture" --key "$tmp/set/key.json" --set "$tmp/set" --out "$tmp/scans" --sheets "$sheets" --dpi 200 --format pdf --degrade copier --seed 9 >/dev/null
pages=$(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['pages']))" "$tmp/scans/truth.json")
inputs=()
for _ in $(seq "$passes"); do inputs+=("$tmp/scans/scans.pdf"); done
/usr/bin/time -f "%e %U %S %M" -o "$tmp/time" "$build/epure" scan "${inputs[@]}" --key "$tmp/set/key.json" \
  --layout "$tmp/scans/layout.json" --out "$tmp/out" --jobs 2 -q "${crops[@]}" 2>/dev/null || true
read -r wall user sys rss < <(tail -n 1 "$tmp/time")  # after "Command exited with non-zero status 1" (duplicates)
total=$((pages * passes))
python3 - "$total" "$wall" "$user" "$sys" "$rss" "$(stat -c %s "$tmp/scans/scans.pdf")" "$pages" <<'PY'
import sys
total, wall, user, sys_, rss, size, pages = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5]), int(sys.argv[6]), int(sys.argv[7])
cpu = user + sys_
print(f"{total} pages ({pages} a pass, PDF {size / pages / 1024:.0f} kB a page): wall {wall:.1f} s, CPU {cpu:.1f} s "
      f"(user {user:.1f}, sys {sys_:.1f}); {total / wall:.1f} pages/s of wall with 2 jobs, "
      f"{total / cpu:.1f} pages/s of CPU ({2 * total / cpu:.1f} on 2 cores); peak memory {rss / 1024:.0f} MB")
PY
