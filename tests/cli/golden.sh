#!/usr/bin/env bash
# Golden files: the course's set for two fixed seeds (2 sheets each, English and French), compared
# byte for byte with the files in tests/golden/, which were looked at (rendered to PNG) before
# they were committed. After a reviewed change of the output, regenerate them with
#   EPURE_UPDATE_GOLDEN=1 EPURE=build/epure EPURE_SOURCE_DIR=$PWD bash tests/cli/golden.sh
# and look at the new ones before committing.
set -u
golden=$EPURE_SOURCE_DIR/tests/golden
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
status=0
# (and the course in space, builtin:3d: its épures)
for case in "en 1" "fr 2" "en 3 builtin:3d"; do
  set -- $case
  lang=$1 seed=$2 spec=${3:-} name=seed$2-$1${3:+-3d}
  "$EPURE" generate --format svg --sheets 2 --seed "$seed" --lang "$lang" ${spec:+--spec "$spec"} --jobs 1 --quiet --out "$tmp/$name" || { echo "generate failed"; exit 1; }
  rm -f "$tmp/$name/index.html" "$tmp/$name/explore.html"  # explore.html: tests/browser
  if [ "${EPURE_UPDATE_GOLDEN:-0}" = 1 ]; then
    rm -rf "$golden/$name"; mkdir -p "$golden"; cp -r "$tmp/$name" "$golden/$name"
    echo "updated $golden/$name"
    continue
  fi
  if ! diff -r "$golden/$name" "$tmp/$name" >/dev/null; then
    echo "FAIL: $name differs from tests/golden/$name:"
    diff -r "$golden/$name" "$tmp/$name" | head -20
    status=1
  fi
done
[ $status -eq 0 ] && echo "golden: ok"
exit $status
