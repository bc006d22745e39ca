#!/usr/bin/env bash
# Memory flat in the length of the stack (issue 30: "memory flat over 1,000 pages"): `epure scan
# --crops` gathers each page as soon as the pages before it are read, writes its crops then and
# drops a duplicate's readings, so its peak resident memory (the child's ru_maxrss, from wait4)
# over a stack given 12 times is within 15 % of that over the stack given 3 times (the later
# copies are duplicates, read in full as the first ones). Before the fix every page's readings
# and crops were held until the end: 165 MB for 240 pages, 407 MB for 960 (bench/README.md,
# "Scan"); here 48 and 192 pages of 4 sheets grew by about 45 MB.
# Not run under the sanitizers (tests/CMakeLists.txt says why).
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$EPURE" generate --format pdf --sheets 4 --seed 5 --lang fr --jobs 1 --quiet --out "$tmp/set" || { echo "FAIL generate"; exit 1; }
"$EPURE_SCAN_FIXTURE" --key "$tmp/set/key.json" --set "$tmp/set" --out "$tmp/scans" --sheets 4 --dpi 200 --format pdf \
  --degrade copier --seed 9 >/dev/null || { echo "FAIL the scans (npm ci in src/scan/classifier?)"; exit 1; }
python3 - "$EPURE" "$tmp" <<'PY'
import csv, os, sys

epure, tmp = sys.argv[1], sys.argv[2]


def peak_kib(passes):
    out = f"{tmp}/out{passes}"
    args = [epure, "scan", *[f"{tmp}/scans/scans.pdf"] * passes, "--key", f"{tmp}/set/key.json",
            "--layout", f"{tmp}/scans/layout.json", "--out", out, "--jobs", "2", "--crops", "-q"]
    env = {k: v for k, v in os.environ.items() if k != "MALLOC_CONF"}  # the program's own settings
    with open(f"{out}.err", "w") as err:
        pid = os.posix_spawn(epure, args, env, file_actions=[(os.POSIX_SPAWN_DUP2, err.fileno(), 2)])
        _, status, usage = os.wait4(pid, 0)
    code = os.waitstatus_to_exitcode(status)
    if code not in (0, 1):  # 1: duplicates and fields to review, as expected
        sys.exit(f"FAIL: epure scan over {passes} copies exited with {code}")
    with open(f"{out}/pages.csv", newline="") as f:
        pages = list(csv.DictReader(f))
    first = len(pages) // passes
    statuses = [p["status"] for p in pages]
    later = ["duplicate" if s == "identified" else s for s in statuses[:first]] * (passes - 1)
    if len(pages) != first * passes or "duplicate" in statuses[:first] or statuses[first:] != later:
        sys.exit(f"FAIL: {passes} copies: the first copy's pages are not the ones read, the later ones their duplicates")
    crops = sum(len(files) for _, _, files in os.walk(f"{out}/crops"))
    return usage.ru_maxrss, len(pages), crops  # KiB on Linux


small, small_pages, small_crops = peak_kib(3)
large, large_pages, large_crops = peak_kib(12)
growth = large / small - 1
print(f"max RSS: {small_pages} pages {small / 1024:.1f} MiB, {large_pages} pages {large / 1024:.1f} MiB ({growth:+.1%})")
failed = False
if small_crops == 0 or small_crops != large_crops:
    print(f"FAIL: crops written: {small_crops} for 3 copies, {large_crops} for 12 (the same, and some)")
    failed = True
if growth > 0.15:
    print("FAIL: the peak memory of epure scan grows with the pages (more than 15 % from 3 copies of the stack to 12)")
    failed = True
sys.exit(1 if failed else 0)
PY
