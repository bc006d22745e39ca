#!/usr/bin/env bash
# The contract's worked examples, end to end: output agrees line for line, exit status is 1
# (the file has bad lines) and every bad line is reported on stderr with its line number.
set -u
here=$EPURE_SOURCE_DIR/tests
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$EPURE" solve "$here/solve/examples/solve.input.jsonl" >"$tmp/out.jsonl" 2>"$tmp/err"
status=$?
[ "$status" -eq 1 ] || { echo "exit status $status, expected 1"; exit 1; }
python3 "$here/tools/compare_jsonl.py" "$tmp/out.jsonl" "$here/solve/examples/solve.expected.jsonl" || exit 1
# nine bad lines, each named with its line number on stderr
[ "$(grep -c 'solve.input.jsonl:[0-9]*: ' "$tmp/err")" -eq 9 ] || { echo "stderr:"; cat "$tmp/err"; exit 1; }
# the same through standard input
"$EPURE" solve <"$here/solve/examples/solve.input.jsonl" >"$tmp/stdin.jsonl" 2>/dev/null
cmp -s "$tmp/out.jsonl" "$tmp/stdin.jsonl" || { echo "stdin output differs from file output"; exit 1; }
echo "solve examples: ok"
