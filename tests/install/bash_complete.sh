# Sourced by the tests: complete_line LINE runs the bash completion's function as bash calls it
# for LINE typed with the cursor at its end, and prints the candidates, one a line, sorted.
# COMP_WORDS is split as bash splits it: at blanks, and at the characters of COMP_WORDBREAKS
# that matter here (':' and '='), each run of which is a word of its own.
complete_line() {
  local line=$1 word part c k breaks
  COMP_LINE=$line
  COMP_POINT=${#line}
  COMP_WORDS=()
  read -ra blank_words <<<"$line"
  for word in "${blank_words[@]}"; do
    part=""
    for ((k = 0; k < ${#word}; k++)); do
      c=${word:k:1}
      # a word ends where a run of break characters starts or stops
      if [[ -n $part ]]; then
        breaks=0
        [[ $c == [:=] ]] && ((breaks += 1))
        [[ ${part: -1} == [:=] ]] && ((breaks += 1))
        if ((breaks == 1)); then
          COMP_WORDS+=("$part")
          part=""
        fi
      fi
      part+=$c
    done
    COMP_WORDS+=("$part")
  done
  [[ $line == *' ' || -z $line ]] && COMP_WORDS+=("")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMPREPLY=()
  _epure
  ((${#COMPREPLY[@]} == 0)) || printf '%s\n' "${COMPREPLY[@]}" | LC_ALL=C sort
}
