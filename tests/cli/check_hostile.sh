#!/usr/bin/env bash
# epure check on the hostile corpus (tests/check/hostile, and two files made here: one past the
# size limit, one with a NUL byte): each file ends with the verdict its first line expects, the
# canary file is untouched, and no process of the sandbox is left. Where this machine has no
# sandbox, epure check must refuse to run (exit status 2) and say why.
set -euo pipefail
: "${EPURE:?}" "${EPURE_SOURCE_DIR:?}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

if ! "$EPURE" check --sandbox-info >"$tmp/info" 2>&1; then
  cat "$tmp/info"
  set +e
  "$EPURE" check "$EPURE_SOURCE_DIR/tests/check/hostile/infinite_loop.c" --out "$tmp/out" 2>"$tmp/err"
  status=$?
  set -e
  [ "$status" -eq 2 ] || { echo "FAIL: without a sandbox, epure check exited $status, not 2"; exit 1; }
  grep -q "refusing to run students' code unconfined" "$tmp/err" || { echo "FAIL: no clear refusal"; cat "$tmp/err"; exit 1; }
  echo "no sandbox here: epure check refused, as it must"
  exit 0
fi

# the canary: a file the hostile code tries to read, overwrite, delete
canary=/tmp/epure-check-canary
head -c 64 /dev/urandom | base64 > "$canary"
chmod 0666 "$canary"
before=$(sha256sum "$canary"; stat -c '%Y %s %a' "$canary")

mkdir "$tmp/made"
{ echo '/* expect: file refused size */'; head -c 300000 /dev/zero | tr '\0' ' '; } > "$tmp/made/huge.c"
printf '/* expect: file refused nul */\nG2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) { return A; }\n\0\n' > "$tmp/made/nul_byte.c"

start=$(date +%s)
mkdir "$tmp/work"
chmod 711 "$tmp" "$tmp/work"  # the sandbox user must reach the programs compiled there
TMPDIR="$tmp/work" "$EPURE" check "$EPURE_SOURCE_DIR/tests/check/hostile" "$tmp/made" --out "$tmp/out" --lang en --jobs 2 \
  --functions Projection --quiet
echo "hostile corpus checked in $(( $(date +%s) - start )) s"
# the same files checked again give the same report, byte for byte (no address, time or pid in it)
TMPDIR="$tmp/work" "$EPURE" check "$EPURE_SOURCE_DIR/tests/check/hostile" "$tmp/made" --out "$tmp/again" --lang en --jobs 2 \
  --functions Projection --quiet
cmp "$tmp/out/report.json" "$tmp/again/report.json" || { echo "FAIL: report.json differs between two runs"; diff "$tmp/out/report.json" "$tmp/again/report.json" | head; exit 1; }

python3 - "$tmp/out/report.json" <<'PY'
import json, re, sys
report = json.load(open(sys.argv[1]))
failures = 0
for f in report["files"]:
    first = open(f["file"], "rb").readline().decode("utf-8", "replace")
    m = re.match(r"/\* expect: (\S+) (\S+)(?: (\S+))? \*/", first)
    if not m:
        print(f"FAIL: {f['file']}: no expect line"); failures += 1; continue
    what, verdict, code = m.groups()
    name = f["file"].split("/")[-1]
    if what == "file":
        got = f["status"]
        got_code = (f.get("refusal") or {}).get("code")
    else:
        fn = f["functions"].get(what)
        if fn is None:
            print(f"FAIL: {name}: no verdict for {what}"); failures += 1; continue
        got, got_code = fn["verdict"], fn.get("reason_code")
    ok = got == verdict and (code is None or got_code == code)
    print(f"{'ok  ' if ok else 'FAIL'} {name}: {got} {got_code or ''} (expected {verdict} {code or ''})")
    failures += not ok
    if what == "Projection" and verdict in ("refused", "timeout", "crashed") and f["status"] == "checked":
        fn = f["functions"]["Projection"]
        if not fn.get("reason"):
            print(f"FAIL: {name}: no reason given"); failures += 1
print(f"{len(report['files']) - failures} passed, {failures} failed")
sys.exit(1 if failures else 0)
PY

after=$(sha256sum "$canary"; stat -c '%Y %s %a' "$canary")
[ "$before" = "$after" ] || { echo "FAIL: the canary changed"; exit 1; }
rm -f "$canary"
# nothing of the sandbox left: no process running a program from, or working in, this run's
# temporary directory (other tests may run sandboxes at the same time), and the directory empty
for p in /proc/[0-9]*; do
  for link in exe cwd; do
    target=$(readlink "$p/$link" 2>/dev/null || true)
    case "$target" in "$tmp"/*) echo "FAIL: process ${p#/proc/} is left ($link $target)"; exit 1 ;; esac
  done
done
[ -z "$(ls -A "$tmp/work")" ] || { echo "FAIL: a temporary directory is left"; ls -la "$tmp/work"; exit 1; }
echo "canary untouched, no process left"
