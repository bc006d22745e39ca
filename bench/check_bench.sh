#!/usr/bin/env bash
# epure check on a class: 30 submissions × the course's 5 functions (Projection, InterSegments,
# rayon_inter_cercle, rayon_inter_cercle_canonique, rayon_inter_carre_canonique), made from the
# test corpus (the mended course and its buggy variants, each cut to the five functions, a
# student's name each), checked with --jobs 2: compiles, runs, judging, bug naming, report,
# marks and the feedback pages (HTML and PDF) included. Prints the wall time and the CPU time
# (user + system of epure and every child: gcc, the linker, the sandboxed programs).
#   bench/check_bench.sh [EPURE] [RUNS]     (EPURE defaults to build/epure)
# Issue 33's target: at most 60 s on 2 cores.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
epure=${1:-$root/build/epure}
runs=${2:-3}
tmp=$(mktemp -d)
chmod 711 "$tmp"
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/class" "$tmp/work"
chmod 711 "$tmp/work"
python3 - "$root/tests/check/corpus" "$tmp/class" <<'PY'
import glob, os, re, sys
corpus, out = sys.argv[1], sys.argv[2]
files = sorted(glob.glob(os.path.join(corpus, "right", "*.c"))) + sorted(glob.glob(os.path.join(corpus, "buggy", "*.c")))
keep = ("Projection", "InterSegments", "rayon_inter_cercle", "rayon_inter_cercle_canonique", "rayon_inter_carre_canonique")
def five(text):
    # cut each file to the course's five functions: drop every other top-level function
    out, skip, depth = [], False, 0
    for line in text.split("\n"):
        m = re.match(r"^(?:bool|G2Xpoint) (\w+)\(", line)
        if m and depth == 0:
            skip = m.group(1) not in keep
        if not skip:
            out.append(line)
        depth += line.count("{") - line.count("}")
        if skip and depth == 0 and "}" in line:
            skip = False
    return "\n".join(out)
for i in range(30):
    src = open(files[i % len(files)]).read()
    src = re.sub(r"student: [^*\n]*", f"student: Student {i + 1:02d} ", src, count=1)
    open(os.path.join(out, f"student{i + 1:02d}.c"), "w").write(five(src))
PY
echo "30 submissions in $tmp/class, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for r in $(seq 1 "$runs"); do
  rm -rf "$tmp/out"
  /usr/bin/time -f "run $r: wall %e s, CPU %U s user + %S s system, peak %M KB" \
    env TMPDIR="$tmp/work" "$epure" check "$tmp/class" --out "$tmp/out" --jobs 2 --quiet \
    --functions Projection,InterSegments,rayon_inter_cercle,rayon_inter_cercle_canonique,rayon_inter_carre_canonique
done
python3 - "$tmp/out/report.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
fns = sum(len(f["functions"]) for f in r["files"])
cases = sum(fn["cases"] for f in r["files"] for fn in f["functions"].values())
print(f"{len(r['files'])} files, {fns} functions, {cases} cases run and judged")
PY
