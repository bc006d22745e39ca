#!/usr/bin/env bash
# `epure grade` never crashes nor hangs, whatever the answers file holds: a short, seeded,
# bounded version of the fuzz run that found two hangs (an expression "√-√" that looped, a
# long line of stray quotes read in quadratic time). 60 files — random bytes, and CSV-ish text
# built from the characters and words the readers care about (delimiters, quotes, CR, LF, BOM,
# NUL, √, sqrt, oui, +x, sheet ids good and bad, ragged rows, truncated files) — each graded
# under `timeout 10`: the exit status must be 0, 1 or 2, and every problem must name the file.
# For a longer run: GRADE_FUZZ_FILES=5000 (the seed is GRADE_FUZZ_SEED, 1 by default).
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$EPURE_SOURCE_DIR/tests/grading/data"
failed=0
fail() { echo "FAIL: $*"; failed=1; }
files=${GRADE_FUZZ_FILES:-60}
# under ASan/UBSan a finding must not pass for exit status 1 ("something could not be read")
export ASAN_OPTIONS="exitcode=86:${ASAN_OPTIONS:-}" UBSAN_OPTIONS="exitcode=86:${UBSAN_OPTIONS:-}"
seed=${GRADE_FUZZ_SEED:-1}

for i in $(seq "$files"); do
  python3 - "$((seed * 100003 + i))" "$tmp/answers.csv" <<'PY'
import random, sys
r = random.Random(int(sys.argv[1]))
sheets = ["1000-0005-002N", "1000-0005-0089", "1000-0005-004H", "1000-0005-003K", "1000-0005-003X", "9999", ""]
cols = ["sheet", "student", "2.t", "2.position", "1.dot", "3.intersects", "1.P.x", "4.faces", "zz", "", "sheet"]
pieces = ["a", "Z", "0", "7", "1", ",", ";", "\t", '"', '""', " ", "\n", "\r\n", "\r", "é", "√", "-", "+", ".", "/",
          "*", "(", ")", "^", "²", "sqrt", "racine", "pi", "oui", "non", "yes", "'", "\ufeff", "\x00", "−", "×",
          "÷", "≈", "e", "s", "p", "r", "+x", "-y", "dedans", "gauche", "avant A", "\u00a0"]
mode = r.randrange(4)
if mode == 0:
    data = bytes(r.randrange(256) for _ in range(r.randrange(0, 4000)))
else:
    d = r.choice([",", ";", "\t"])
    hdr = r.sample(cols, r.randrange(0, len(cols)))
    if mode > 1 and "sheet" not in hdr: hdr.insert(0, "sheet")
    lines = [d.join(hdr)]
    for _ in range(r.randrange(0, 50)):
        cells = [r.choice(sheets) if h == "sheet" and r.random() < .8
                 else "".join(r.choice(pieces) for _ in range(r.randrange(0, 9))) for h in hdr]
        if r.random() < .2: cells = cells[:r.randrange(len(cells) + 1)]
        if r.random() < .1: cells += ["x"] * r.randrange(4)
        lines.append(d.join(cells))
    text = r.choice(["\n", "\r\n", "\r"]).join(lines)
    if r.random() < .3: text = "\ufeff" + text
    data = text.encode("utf-8")
    if mode == 3 and data:
        data = bytearray(data)
        for _ in range(r.randrange(1, 20)): data[r.randrange(len(data))] = r.randrange(256)
        data = bytes(data[:r.randrange(len(data) + 1)])
open(sys.argv[2], "wb").write(data)
PY
  timeout 10 "$EPURE" grade --key "$data/key_small.json" --answers "$tmp/answers.csv" --json "$tmp/m.json" \
    --report "$tmp/r.csv" -q >/dev/null 2>"$tmp/err"
  st=$?
  if [ "$st" -gt 2 ] || grep -aq -e "ERROR: AddressSanitizer" -e "runtime error:" "$tmp/err"; then
    cp "$tmp/answers.csv" "/tmp/grade_fuzz_failure_$i.csv" 2>/dev/null
    fail "file $i (seed $seed): exit $st (124 = hung) — kept as /tmp/grade_fuzz_failure_$i.csv: $(head -c 300 "$tmp/err")"
    continue
  fi
  grep -a -v -e "^\(epure grade: \)\?$tmp/answers.csv" -e "^\(epure grade: \)\?$data/key_small.json" -e "^$" "$tmp/err" | head -1 | grep -aq . &&
    { cp "$tmp/answers.csv" "/tmp/grade_fuzz_failure_$i.csv"; fail "file $i: a line of stderr not starting with the file: $(grep -a -v -e "^$tmp/answers.csv" -e "^$data/key_small.json" "$tmp/err" | head -1 | cut -c1-200)"; }
done

[ "$failed" -eq 0 ] && echo "grade_fuzz: $files files, no crash, no hang"
exit "$failed"
