#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then the installed epure as a user meets it: in the
# GNU directories, `--version` with both versions (the program's as CMakeLists.txt's project()
# sets it), a set written from another directory, a manual page per command that man renders
# without a warning and that lists every option of the command's --help with its default, and
# the completion scripts (bash -n, zsh -n).
# Environment: EPURE_BUILD_DIR (the build to install), EPURE_SOURCE_DIR.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

prefix=$tmp/prefix
cmake --install "$EPURE_BUILD_DIR" --prefix "$prefix" >"$tmp/install.log" || fail "cmake --install: $(cat "$tmp/install.log")"
epure=$prefix/bin/epure
for f in bin/epure share/man/man1/epure.1.gz share/man/man1/epure-generate.1.gz share/man/man1/epure-grade.1.gz \
  share/bash-completion/completions/epure share/zsh/site-functions/_epure share/doc/epure/README.md; do
  [ -e "$prefix/$f" ] || fail "not installed: $f (installed: $(cd "$prefix" && find . -type f | sort | tr '\n' ' '))"
done

# --version: the program's version, one place (project(VERSION) in CMakeLists.txt), and the draw version
version=$(sed -n 's/^project(epure VERSION \([0-9.]*\).*/\1/p' "$EPURE_SOURCE_DIR/CMakeLists.txt")
draw=$(sed -n 's/.*kDrawVersion = \([0-9]*\);.*/\1/p' "$EPURE_SOURCE_DIR/src/exercises/sheet_id.h")
[ -n "$version" ] && [ -n "$draw" ] || fail "cannot read the versions from the sources"
[ "$("$epure" --version)" = "epure $version (draw version $draw)" ] || fail "--version: $("$epure" --version)"

# a set written from another directory, by the installed program alone (nothing read from the tree)
mkdir "$tmp/elsewhere"
(cd "$tmp/elsewhere" && "$epure" generate --sheets 2 --jobs 1 -q) || fail "generate from another directory"
for f in key.json sheets.pdf keys.pdf index.html; do [ -s "$tmp/elsewhere/out/$f" ] || fail "generate wrote no out/$f"; done
[ "$(ls "$tmp/elsewhere/out/sheets" | wc -l)" = 2 ] || fail "generate: not 2 sheets"

# The commands, as `--help` lists them (CLI11's help: the lines under "Subcommands:"), recursively.
commands() {  # commands WORDS...: the subcommands of `epure WORDS`
  "$epure" "$@" --help | awk '/^Subcommands:/ { on = 1; next } on && /^  [a-z]/ { print $1 } on && /^$/ { on = 0 }'
}
all=("")
queue=("")
while [ ${#queue[@]} -gt 0 ]; do
  path=${queue[0]}
  queue=("${queue[@]:1}")
  for sub in $(commands $path); do
    all+=("${path:+$path }$sub")
    queue+=("${path:+$path }$sub")
  done
done
[ ${#all[@]} -ge 8 ] || fail "only ${#all[@]} commands in --help: ${all[*]}"

pages=$(ls "$prefix/share/man/man1" | wc -l)
[ "$pages" = ${#all[@]} ] || fail "$pages manual pages for ${#all[@]} commands: $(ls "$prefix/share/man/man1")"
export MANPAGER=cat MANWIDTH=100
for path in "${all[@]}"; do
  page=$prefix/share/man/man1/epure${path:+-${path// /-}}.1.gz
  [ -f "$page" ] || fail "no manual page for 'epure $path'"
  # rendered by man as a user reads it, groff's warnings on (none expected), in ASCII to compare
  man --warnings=all -E ascii -l "$page" >"$tmp/page.txt" 2>"$tmp/page.err" || fail "man -l $page: $(cat "$tmp/page.err")"
  [ ! -s "$tmp/page.err" ] || fail "man -l $page warns: $(cat "$tmp/page.err")"
  tr '\n' ' ' <"$tmp/page.txt" | tr -s ' ' >"$tmp/page.flat"  # lines as filled at MANWIDTH, joined
  # every option the command's --help shows is in its page, and every default the help shows too
  "$epure" $path --help >"$tmp/help.txt"
  for option in $(grep -oE '^ +(-[a-zA-Z],)?--?[a-z][a-z-]*' "$tmp/help.txt" | tr ',' ' '); do
    grep -qe "$option" "$tmp/page.flat" || fail "'epure $path': $option of --help is not in $(basename "$page")"
  done
  # (CLI11 writes a default after the value's type, "=30", a list's as "=[svg,pdf] ...")
  for default in $(grep -E '^ +-' "$tmp/help.txt" | grep -oE '=[^ =]+( \.\.\.)?$' | sed 's/ \.\.\.$//; s/^=//; s/^\[\(.*\)\]$/\1/'); do
    grep -qF "Default: $default." "$tmp/page.flat" || fail "'epure $path': default $default of --help is not in $(basename "$page")"
  done
done
# the root page names every command; generate's lists its options' defaults and the built-in specs
man -E ascii -l "$prefix/share/man/man1/epure.1.gz" >"$tmp/epure.txt"
for path in "${all[@]:1}"; do
  grep -q "epure-${path// /-}(1)" "$tmp/epure.txt" || fail "epure(1) does not name epure-${path// /-}(1)"
done
man -E ascii -l "$prefix/share/man/man1/epure-generate.1.gz" >"$tmp/generate.txt"
grep -q 'Default: 30\.' "$tmp/generate.txt" || fail "epure-generate(1): no default of --sheets"
grep -q 'builtin:3d' "$tmp/generate.txt" || fail "epure-generate(1): no builtin:3d"

# the completion scripts parse
bash -n "$prefix/share/bash-completion/completions/epure" || fail "bash -n"
if command -v zsh >/dev/null; then
  zsh -n "$prefix/share/zsh/site-functions/_epure" || fail "zsh -n"
else
  echo "prefix.sh: zsh -n SKIPPED: zsh is missing (apt-get install zsh)"
fi
echo "prefix.sh: OK (${#all[@]} commands, each with its page)"
