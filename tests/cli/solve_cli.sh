#!/usr/bin/env bash
# The command line around `epure solve`: help and version, usage errors (one line on stderr,
# exit 2), a missing file, blank lines, CRLF, an empty file, standard input, exit statuses.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

# run NAME ARGS...: stdout, stderr and status of `epure ARGS` kept as $tmp/NAME.{out,err,status}
run() {
  local name=$1; shift
  "$EPURE" "$@" >"$tmp/$name.out" 2>"$tmp/$name.err" <"${STDIN:-/dev/null}"
  echo $? >"$tmp/$name.status"
}
status() { cat "$tmp/$1.status"; }
lines() { wc -l <"$1" | tr -d ' '; }

# --- help and version: exit 0, something sensible on stdout --------------------------------
run help --help
[ "$(status help)" -eq 0 ] || fail "--help: exit $(status help)"
grep -q solve "$tmp/help.out" || fail "--help does not mention the solve command"
run version --version
[ "$(status version)" -eq 0 ] || fail "--version: exit $(status version)"
grep -Eq '^epure [0-9]+\.[0-9]+' "$tmp/version.out" || fail "--version printed: $(cat "$tmp/version.out")"
run solve_help solve --help
[ "$(status solve_help)" -eq 0 ] || fail "solve --help: exit $(status solve_help)"
grep -qi 'file' "$tmp/solve_help.out" || fail "solve --help does not mention its FILE argument"
grep -q 'ray_circle' "$tmp/solve_help.out" || fail "solve --help does not list the kinds"

# --- usage errors: one line on stderr, nothing on stdout, exit 2 ----------------------------
usage_error() {  # NAME ARGS...
  local name=$1; shift
  run "$name" "$@"
  [ "$(status "$name")" -eq 2 ] || fail "epure $*: exit $(status "$name"), expected 2"
  [ "$(lines "$tmp/$name.err")" -eq 1 ] || fail "epure $*: stderr is not one line: $(cat "$tmp/$name.err")"
  [ -s "$tmp/$name.out" ] && fail "epure $*: wrote to stdout"
  return 0
}
usage_error unknown_option --frobnicate
usage_error unknown_command frobnicate
usage_error unknown_solve_option solve --frobnicate
usage_error solve_two_files solve a.jsonl b.jsonl
usage_error no_command

# --- a missing input file: a clear error naming it, non-zero, nothing on stdout -------------
run missing solve "$tmp/no-such-file.jsonl"
[ "$(status missing)" -ne 0 ] || fail "missing file: exit 0"
grep -q 'no-such-file.jsonl' "$tmp/missing.err" || fail "missing file: stderr does not name it: $(cat "$tmp/missing.err")"
[ -s "$tmp/missing.out" ] && fail "missing file: wrote to stdout"

# --- input handling -------------------------------------------------------------------------
good1='{"kind":"vectors","u":[3,4],"v":[-4,3]}'
good2='{"kind":"ray_circle","A":[-5,0],"u":[1,0],"C":[0,0],"r":3}'
good3='{"kind":"ray_square","A":[0,0],"u":[0,-2]}'
bad='{"kind":"ray_circle","A":[-5,0],"u":[0,0],"C":[0,0],"r":3}'
printf '%s\n%s\n%s\n' "$good1" "$good2" "$good3" >"$tmp/good.jsonl"

# only good lines: exit 0, nothing on stderr, one line each
run good solve "$tmp/good.jsonl"
[ "$(status good)" -eq 0 ] || fail "good lines: exit $(status good)"
[ -s "$tmp/good.err" ] && fail "good lines: stderr: $(cat "$tmp/good.err")"
[ "$(lines "$tmp/good.out")" -eq 3 ] || fail "good lines: $(lines "$tmp/good.out") output lines, expected 3"
grep -q '"angle_deg":90' "$tmp/good.out" || fail "good lines: unexpected output: $(head -n 1 "$tmp/good.out")"

# blank lines (empty, spaces, tabs) are skipped, not answered
printf '\n%s\n   \n\t\n%s\n \t \n\n%s\n\n' "$good1" "$good2" "$good3" >"$tmp/blank.jsonl"
run blank solve "$tmp/blank.jsonl"
[ "$(status blank)" -eq 0 ] || fail "blank lines: exit $(status blank)"
cmp -s "$tmp/blank.out" "$tmp/good.out" || fail "blank lines: output differs from the same lines without blanks"

# CRLF line ends, a blank CRLF line included, give the same output
printf '%s\r\n\r\n%s\r\n%s\r\n' "$good1" "$good2" "$good3" >"$tmp/crlf.jsonl"
run crlf solve "$tmp/crlf.jsonl"
[ "$(status crlf)" -eq 0 ] || fail "CRLF: exit $(status crlf): $(cat "$tmp/crlf.err")"
cmp -s "$tmp/crlf.out" "$tmp/good.out" || fail "CRLF: output differs from LF output"

# a last line without its newline is still solved
printf '%s\n%s\n%s' "$good1" "$good2" "$good3" >"$tmp/noeol.jsonl"
run noeol solve "$tmp/noeol.jsonl"
cmp -s "$tmp/noeol.out" "$tmp/good.out" || fail "no final newline: output differs"

# an empty file, or one of blank lines only: no output, exit 0
: >"$tmp/empty.jsonl"
run empty solve "$tmp/empty.jsonl"
[ "$(status empty)" -eq 0 ] || fail "empty file: exit $(status empty)"
[ -s "$tmp/empty.out" ] && fail "empty file: output $(cat "$tmp/empty.out")"
printf '\n  \n\r\n' >"$tmp/blanks.jsonl"
run blanks solve "$tmp/blanks.jsonl"
[ "$(status blanks)" -eq 0 ] || fail "blank file: exit $(status blanks)"
[ -s "$tmp/blanks.out" ] && fail "blank file: output $(cat "$tmp/blanks.out")"

# standard input, with no argument and with '-'
STDIN=$tmp/good.jsonl run stdin solve
[ "$(status stdin)" -eq 0 ] || fail "stdin: exit $(status stdin)"
cmp -s "$tmp/stdin.out" "$tmp/good.out" || fail "stdin: output differs from file output"
STDIN=$tmp/good.jsonl run stdin_dash solve -
cmp -s "$tmp/stdin_dash.out" "$tmp/good.out" || fail "stdin '-': output differs from file output"
STDIN=$tmp/empty.jsonl run stdin_empty solve
[ "$(status stdin_empty)" -eq 0 ] && [ ! -s "$tmp/stdin_empty.out" ] || fail "empty stdin: exit $(status stdin_empty)"

# a bad line in the middle: exit 1, an error object in its place, the rest still solved, and
# stderr names its line number (blank lines count)
printf '%s\n\n%s\n%s\n' "$good1" "$bad" "$good3" >"$tmp/mixed.jsonl"
run mixed solve "$tmp/mixed.jsonl"
[ "$(status mixed)" -eq 1 ] || fail "bad line: exit $(status mixed), expected 1"
[ "$(lines "$tmp/mixed.out")" -eq 3 ] || fail "bad line: $(lines "$tmp/mixed.out") output lines, expected 3"
sed -n 2p "$tmp/mixed.out" | grep -q '^{"error":"[^"]*u[^"]*"}$' || fail "bad line: $(sed -n 2p "$tmp/mixed.out")"
sed -n 3p "$tmp/mixed.out" | grep -q '"hit":true' || fail "line after the bad one: $(sed -n 3p "$tmp/mixed.out")"
grep -q 'mixed.jsonl:3:' "$tmp/mixed.err" || fail "bad line: stderr does not give line 3: $(cat "$tmp/mixed.err")"

# the same through stdin
STDIN=$tmp/mixed.jsonl run mixed_stdin solve
[ "$(status mixed_stdin)" -eq 1 ] || fail "bad line on stdin: exit $(status mixed_stdin)"
cmp -s "$tmp/mixed_stdin.out" "$tmp/mixed.out" || fail "bad line on stdin: output differs"

[ "$failed" -eq 0 ] && echo "solve cli: ok"
exit "$failed"
