#!/usr/bin/env bash
# The Debian package as CI builds it: `cpack -G DEB` into a temporary directory, then checked:
# its name and Version (the project's), its Depends (computed by dpkg-shlibdeps: every library
# the binary is linked with, found by objdump and dpkg -S here, is there by its package, jemalloc
# included; and the PDFs' font), its files; then unpacked into a throw-away root (dpkg -x) and
# run from another directory: a set written, a manual page read with man -l, the completion
# script parsed and asked for `epure gen<Tab>` and `epure preview <Tab>`.
# Environment: EPURE_BUILD_DIR, EPURE_SOURCE_DIR. Skipped (77) without dpkg-shlibdeps (dpkg-dev).
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
if ! command -v dpkg-shlibdeps >/dev/null; then
  echo "package.sh: SKIPPED: dpkg-shlibdeps is missing (apt-get install dpkg-dev)"
  exit 77
fi

cpack -G DEB --config "$EPURE_BUILD_DIR/CPackConfig.cmake" -B "$tmp/pkg" >"$tmp/cpack.log" 2>&1 || fail "cpack: $(cat "$tmp/cpack.log")"
version=$(sed -n 's/^project(epure VERSION \([0-9.]*\).*/\1/p' "$EPURE_SOURCE_DIR/CMakeLists.txt")
deb=$tmp/pkg/epure_${version}_$(dpkg --print-architecture).deb
[ -f "$deb" ] || fail "no $(basename "$deb"): $(ls "$tmp/pkg")"
[ "$(dpkg-deb -f "$deb" Package)" = epure ] || fail "Package: $(dpkg-deb -f "$deb" Package)"
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "Version: $(dpkg-deb -f "$deb" Version)"

# Depends: the package of every library the binary needs, and the font
depends=$(dpkg-deb -f "$deb" Depends)
echo "package.sh: Depends: $depends"
dpkg-deb -x "$deb" "$tmp/root"
epure=$tmp/root/usr/bin/epure
needed=$(objdump -p "$epure" | awk '$1 == "NEEDED" { print $2 }')
[ -n "$needed" ] || fail "objdump finds no NEEDED library in $epure"
sed 's/ *([^)]*)//g; s/, */\n/g' <<<"$depends" >"$tmp/depends"  # the package names, one a line
ldconfig -p >"$tmp/ldconfig"
for lib in $needed; do
  path=$(awk -v lib="$lib" '$1 == lib && /x86-64|64bit/ { print $NF; exit }' "$tmp/ldconfig")
  [ -n "$path" ] || path=$(awk -v lib="$lib" '$1 == lib { print $NF; exit }' "$tmp/ldconfig")
  [ -n "$path" ] || fail "$lib: not found by ldconfig"
  package=$(dpkg -S "$path" 2>/dev/null | sed -n '1s/:.*//p') || true
  [ -n "$package" ] || package=$(dpkg -S "$(readlink -f "$path")" 2>/dev/null | sed -n '1s/:.*//p') || true
  [ -n "$package" ] || fail "$lib ($path): no package owns it"
  grep -qxF "$package" "$tmp/depends" || fail "Depends lacks $package (for $lib): $depends"
done
if grep -q libjemalloc "$EPURE_BUILD_DIR/CMakeCache.txt" && objdump -p "$epure" | grep -q 'NEEDED.*libjemalloc'; then
  grep -qx 'libjemalloc2' "$tmp/depends" || fail "Depends lacks libjemalloc2: $depends"
fi
grep -qx 'fonts-dejavu-core' "$tmp/depends" || fail "Depends lacks fonts-dejavu-core: $depends"

dpkg-deb -c "$deb" | awk '{ print $NF }' >"$tmp/files"
for f in ./usr/bin/epure ./usr/share/man/man1/epure.1.gz ./usr/share/man/man1/epure-grade.1.gz \
  ./usr/share/bash-completion/completions/epure ./usr/share/zsh/vendor-completions/_epure ./usr/share/doc/epure/README.md; do
  grep -qxF "$f" "$tmp/files" || fail "not in the package: $f"
done

# unpacked and run from another directory
mkdir "$tmp/elsewhere"
(cd "$tmp/elsewhere" && "$epure" generate --sheets 2 --jobs 1 -q) || fail "the packaged epure: generate"
[ -s "$tmp/elsewhere/out/key.json" ] && [ -s "$tmp/elsewhere/out/sheets.pdf" ] || fail "the packaged epure wrote no set"
"$epure" --version | grep -qx "epure $version (draw version [0-9]*)" || fail "--version: $("$epure" --version)"
MANPAGER=cat man -E ascii -l "$tmp/root/usr/share/man/man1/epure-grade.1.gz" >"$tmp/grade.txt" 2>"$tmp/man.err" ||
  fail "man -l epure-grade.1.gz: $(cat "$tmp/man.err")"
grep -q -- '--answers' "$tmp/grade.txt" || fail "epure-grade(1) has no --answers"
script=$tmp/root/usr/share/bash-completion/completions/epure
bash -n "$script" || fail "bash -n on the packaged completion"
source "$script"
source "$(dirname "$0")/bash_complete.sh"
[ "$(complete_line "epure gen")" = generate ] || fail "packaged completion of 'epure gen': $(complete_line "epure gen")"
kinds=$("$epure" kinds --json | python3 -c 'import json, sys; print("\n".join(sorted(k["name"] for k in json.load(sys.stdin))))')
[ "$(complete_line "epure preview ")" = "$(LC_ALL=C sort <<<"$kinds")" ] || fail "packaged completion of 'epure preview ': $(complete_line "epure preview " | tr '\n' ' ')"
echo "package.sh: OK ($(basename "$deb"), $(du -k "$deb" | cut -f1) KiB)"
