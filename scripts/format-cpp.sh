#!/bin/sh
# Formats the C++ (cpp/, bindings/, bench/, tests/) with the repo's .clang-format.
#   sh scripts/format-cpp.sh           # rewrites the files in place
#   sh scripts/format-cpp.sh --check   # changes nothing; fails and lists what differs
# The reference is Debian 12's clang-format 14, which CI runs; other versions may differ
# on a few lines.
set -eu
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null 2>&1 || {
  echo "format-cpp: clang-format is missing (Debian: apt-get install clang-format)" >&2
  exit 1
}
files=$(find cpp bindings bench tests -type f \( -name '*.cpp' -o -name '*.h' \) | sort)
if [ "${1:-}" = --check ]; then
  # shellcheck disable=SC2086
  clang-format --dry-run -Werror $files || {
    echo "format-cpp: run 'npm run format' to format the C++ files above" >&2
    exit 1
  }
else
  # shellcheck disable=SC2086
  clang-format -i $files
fi
