#!/bin/sh
# `npm run test:js`: the wasm, rebuilt when web/dist is older than its sources (the rule of
# scripts/ensure-deps.sh, which also installs what is missing), then the node tests of
# tests/js/, or of the files and folders given:
#
#   npm run test:js -- tests/js/refine.test.js
set -eu
cd "$(dirname "$0")/.."
sh scripts/ensure-deps.sh js
[ $# -gt 0 ] || set -- tests/js/
# A folder becomes its test files: from Node 21 on, node --test takes glob patterns, not
# folders.
files=""
for arg in "$@"; do
  if [ -d "$arg" ]; then
    for file in "${arg%/}"/*.test.js "${arg%/}"/*.test.mjs; do
      [ -e "$file" ] && files="$files $file"
    done
  else
    files="$files $arg"
  fi
done
# shellcheck disable=SC2086
node --test $files
