#!/usr/bin/env bash
# `epure grade` end to end: answer rows per second on one core, and peak memory against the
# number of rows (it should stay flat: marking streams). Makes a set of SHEETS sheets of the
# course's worksheet (key.json), then ROWS answer rows as a French spreadsheet exports them
# (semicolons, decimal commas, CRLF, quoted names), cycling through the sheets: about 70 % of
# the answers right, the rest rounded differently, wrong, blank, or a named mistake; and times
# `taskset -c CPU epure grade --key … --answers … --report …` over RUNS runs (median), once
# with ROWS rows and once with ROWS/10, printing rows/s and the peak resident memory of each
# (GNU time's maximum RSS). A run whose exit status is 2 (nothing graded) stops the benchmark.
#
#   bench/grade_bench.sh [BUILD_DIR] [ROWS] [RUNS] [CPU] [SHEETS]     EPURE=path for another binary
set -eu
build=${1:-build-bench}
rows=${2:-1000000}
runs=${3:-5}
cpu=${4:-0}
sheets=${5:-1000}
epure=${EPURE:-$build/epure}
work=${BENCH_DIR:-$(mktemp -d)}
trap '[ -z "${BENCH_DIR:-}" ] && rm -rf "$work"' EXIT

"$epure" generate --format svg --sheets "$sheets" --seed 11 --out "$work/set" --quiet --jobs 2
python3 - "$work/set/key.json" "$work/answers.csv" "$rows" <<'PY'
import csv, json, random, sys
key = json.load(open(sys.argv[1]))
rows = int(sys.argv[3])
rng = random.Random(20261123)
ids = []
place = {}  # a question's exercise by its place on the sheet (ids start with the course's number: "P.dot", "3.3.t")
for s in key["sheets"]:
    for e in s["exercises"]:
        for q in e["questions"]:
            if q["id"] not in ids: ids.append(q["id"])
            place.setdefault(q["id"], e["n"])
order = {q: i for i, q in enumerate(ids)}
ids.sort(key=lambda q: (place[q], order[q]))
def num(x): return f"{x:.2f}".replace(".", ",")
def answer(q):
    e, r = q["expected"], rng.random()
    if r < 0.05: return ""
    if isinstance(e, bool): return ("oui" if e else "non") if r < 0.9 else ("non" if e else "oui")
    if isinstance(e, (int, float)):
        if r < 0.75: return num(e)
        if r < 0.85: return num(e + 0.004)
        if r < 0.92: return num(-e)
        return num(e * 1.7 + 0.3)
    if isinstance(e, list): return " ".join(e) if e else "aucun"
    return {"before": "avant A", "between": "entre", "after": "après B"}.get(e, e) if r < 0.9 else "derrière"
# rows are built per sheet once, then cycled: the file's content, not Python, is what is timed
per_sheet = []
for s in key["sheets"]:
    cells = {q["id"]: answer(q) for e in s["exercises"] for q in e["questions"]}
    per_sheet.append([s["id"]] + [cells.get(q, "") for q in ids])
with open(sys.argv[2], "w", newline="", encoding="utf-8-sig") as f:
    w = csv.writer(f, delimiter=";", lineterminator="\r\n")
    w.writerow(["sheet", "student"] + ids)
    for i in range(rows):
        row = per_sheet[i % len(per_sheet)]
        w.writerow([row[0], f"Étudiant {i}, groupe {i % 7}"] + row[1:])
PY
head -n $((rows / 10 + 1)) "$work/answers.csv" >"$work/answers_tenth.csv"

measure() {  # FILE ROWS
  local file=$1 n=$2 times=() peak=0
  for _ in $(seq "$runs"); do
    /usr/bin/time -f "%e %M" -o "$work/time" taskset -c "$cpu" "$epure" grade --key "$work/set/key.json" \
      --answers "$file" --report "$work/report.csv" -q >/dev/null 2>"$work/err" && st=0 || st=$?
    [ "$st" -le 1 ] || { echo "epure grade failed (exit $st): $(head -3 "$work/err")" >&2; exit 1; }
    local reported
    reported=$(($(wc -l <"$work/report.csv") - 1))
    [ "$reported" -eq "$n" ] || { echo "rows in $n, reported $reported" >&2; exit 1; }
    read -r secs kb < <(tail -1 "$work/time")
    times+=("$secs")
    [ "$kb" -gt "$peak" ] && peak=$kb
  done
  local median
  median=$(printf '%s\n' "${times[@]}" | sort -n | sed -n "$(( (runs + 1) / 2 ))p")
  python3 -c "import sys; n,s,kb=int(sys.argv[1]),float(sys.argv[2]),int(sys.argv[3]); print(f'{n:>8} rows  median {s:.2f} s  {n/s:>9,.0f} rows/s  peak {kb/1024:.1f} MiB')" \
    "$n" "$median" "$peak"
}
echo "epure grade, $sheets-sheet key, $(du -h "$work/answers.csv" | cut -f1) of answers, CPU $cpu, $runs runs:"
measure "$work/answers_tenth.csv" $((rows / 10))
measure "$work/answers.csv" "$rows"
