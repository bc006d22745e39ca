#!/usr/bin/env bash
# The shell completions the build wrote (epure __docs): bash's function called as bash calls it
# (bash_complete.sh) on subcommands, options, choices read from the program (the kinds as
# `epure kinds --json` lists them, the built-in specs behind --spec builtin:), file names; then
# real interactive bash and zsh in a pseudo-terminal (tab_complete.py), Tab pressed: what a user
# gets, the shells' own word splitting included.
# Environment: EPURE (the built program), EPURE_BUILD_DIR, EPURE_SOURCE_DIR.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
here=$(cd "$(dirname "$0")" && pwd)
script=$EPURE_BUILD_DIR/docs/bash-completion/epure
zsh_script=$EPURE_BUILD_DIR/docs/zsh/_epure

bash -n "$script" || fail "bash -n $script"
# `epure completion bash|zsh` prints what the build installs
cmp -s <("$EPURE" completion bash) "$script" || fail "epure completion bash differs from $script"
cmp -s <("$EPURE" completion zsh) "$zsh_script" || fail "epure completion zsh differs from $zsh_script"

source "$script"
source "$here/bash_complete.sh"
expect() {  # expect LINE CANDIDATES...: the candidates for LINE, exactly (sorted)
  local line=$1
  shift
  local got want
  got=$(complete_line "$line")
  want=$(printf '%s\n' "$@" | LC_ALL=C sort)  # nothing: an empty line, dropped by $()
  [ "$got" = "$want" ] || fail "completing '$line': got [$(echo $got)], want [$(echo $want)]"
}

subcommands=$("$EPURE" --help | awk '/^Subcommands:/ { on = 1; next } on && /^  [a-z]/ { print $1 } on && /^$/ { on = 0 }')
expect "epure gen" generate
expect "epure " $subcommands
expect "epure export " moodle qti
expect "epure export q" qti
expect "epure --v" --version
expect "epure generate --s" --seed --sheets --spec --split
expect "epure generate --lang " en fr
expect "epure generate --lang=f" fr
expect "epure generate --format " pdf svg
expect "epure generate --format svg," svg,pdf
expect "epure generate --difficulty h" hard
expect "epure generate --sheets " # a number: nothing to offer
expect "epure generate -n 3 --sh" --sheets
expect "epure grade --delimiter " '\,' '\;' tab '\\t'  # as they are to be typed
expect "epure export qti --image " png svg
# the kinds, as the program lists them
kinds=$("$EPURE" kinds --json | python3 -c 'import json, sys; print(" ".join(k["name"] for k in json.load(sys.stdin)))')
[ -n "$kinds" ] || fail "epure kinds --json lists no kind"
expect "epure preview " $kinds
expect "epure preview --seed 3 " $kinds
expect "epure preview ray_ci" $(printf '%s\n' $kinds | grep '^ray_ci')
expect "epure preview dot_product --" $(complete_line "epure preview --")
# --spec: files and the built-in specs; bash completes what follows the ':'
cd "$tmp"
mkdir sub
touch spec-a.toml answers.csv
expect "epure generate --spec spec" spec-a.toml
expect "epure generate --spec buil" builtin builtin:3d
expect "epure generate --spec builtin:" 3d
expect "epure generate --spec=builtin:" 3d
expect "epure grade --spec builtin:3" 3d
expect "epure grade --answers an" answers.csv
expect "epure grade --answers s" spec-a.toml sub
expect "epure solve s" spec-a.toml sub
expect "epure completion " bash zsh

# Tab in real shells: the unique completions a user types, each line as the shell completed it
check_tab() {  # check_tab SHELL SCRIPT LINE EXPECTED [LINE EXPECTED]...
  local shell=$1 script=$2 lines=() expected=() got
  shift 2
  while [ $# -gt 0 ]; do
    lines+=("$1")
    expected+=("$2")
    shift 2
  done
  got=$(python3 "$here/tab_complete.py" "$shell" "$script" "$(dirname "$EPURE")" "${lines[@]}") || fail "$shell: $got"
  [ "$got" = "$(printf '%s\n' "${expected[@]}")" ] ||
    fail "$shell: Tab gave [$(echo "$got" | paste -sd '|')], want [$(printf '%s|' "${expected[@]}")]"
}
check_tab bash "$script" \
  "epure gen" "epure generate " \
  "epure generate --spec builtin:" "epure generate --spec builtin:3d " \
  "epure generate --spec=builtin:" "epure generate --spec=builtin:3d " \
  "epure preview ray_ci" "epure preview ray_circle " \
  "epure generate --format svg," "epure generate --format svg,pdf " \
  "epure grade --answers an" "epure grade --answers answers.csv "
if command -v zsh >/dev/null; then
  zsh -n "$zsh_script" || fail "zsh -n $zsh_script"
  check_tab zsh "$zsh_script" \
    "epure gen" "epure generate " \
    "epure generate --lang f" "epure generate --lang fr " \
    "epure generate --spec builtin:" "epure generate --spec builtin:3d " \
    "epure preview ray_ci" "epure preview ray_circle " \
    "epure export q" "epure export qti " \
    "epure generate --format svg," "epure generate --format svg,pdf," \
    "epure grade --answers an" "epure grade --answers answers.csv "
else
  echo "completion.sh: zsh SKIPPED: zsh is missing (apt-get install zsh)"
fi
echo "completion.sh: OK"
