#!/bin/sh
# Formats the C++ (cpp/, bindings/, bench/, tests/) with the repo's .clang-format.
#   sh scripts/format-cpp.sh           # rewrites the files in place
#   sh scripts/format-cpp.sh --check   # changes nothing; fails and lists what differs
# The reference is clang-format 14 (Debian 12's), which CI runs: clang-format-14 is preferred
# where several are installed, CLANG_FORMAT names another. Other versions lay out a few lines
# differently; with one of them the check reports the differences without failing.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/scripts/versions.sh"
cd "$root"
format=${CLANG_FORMAT:-}
if [ -z "$format" ]; then
  for candidate in clang-format-14 clang-format; do
    if command -v "$candidate" >/dev/null 2>&1; then
      format=$candidate
      break
    fi
  done
fi
if [ -z "$format" ] || ! command -v "$format" >/dev/null 2>&1; then
  echo "format-cpp: clang-format is missing (Debian: apt-get install clang-format)" >&2
  exit 1
fi
version=$("$format" --version | first_version)
reference=yes
case $version in 14.*) ;; *) reference=no ;; esac
other_version() {
  echo "format-cpp: $format is version ${version:-unknown}; CI checks the format with" \
    "clang-format 14 (Debian 12), and other versions lay out a few lines differently." >&2
}

files=$(find cpp bindings bench tests -type f \( -name '*.cpp' -o -name '*.h' \) | sort)
if [ "${1:-}" = --check ]; then
  # shellcheck disable=SC2086
  "$format" --dry-run -Werror $files && exit 0
  if [ "$reference" = yes ]; then
    echo "format-cpp: run 'npm run format' to format the C++ files above" >&2
    exit 1
  fi
  other_version
  echo "format-cpp: so the differences above may be that version's rather than yours: not" \
    "counted as a failure here (CI will count them if 14 finds them too). For CI's check," \
    "install clang-format-14 (Debian, Ubuntu: apt-get install clang-format-14) or point" \
    "CLANG_FORMAT at one." >&2
else
  [ "$reference" = yes ] || other_version
  # shellcheck disable=SC2086
  "$format" -i $files
fi
