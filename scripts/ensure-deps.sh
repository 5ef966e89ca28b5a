#!/bin/sh
# Installs what a fresh Debian machine lacks for one task, checks the versions of the tools
# found, installs the npm dev dependencies, and builds the wasm when web/dist is missing or
# older than its sources. As root it installs Debian packages; otherwise it prints the exact
# command to run and fails.
#
#   sh scripts/ensure-deps.sh demo   # `npm run demo`: CMake, make, Emscripten, node
#   sh scripts/ensure-deps.sh cpp    # `npm run test:cpp`: CMake, make, g++, GoogleTest, GMP
#   sh scripts/ensure-deps.sh js     # `npm run test:js`: as demo
#   sh scripts/ensure-deps.sh        # `npm test`: all of those, clang, clang-format, Chromium
# Every profile needs the USGS elevation models (python-matplotlib-data) of the terrain page,
# tests and bench.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/scripts/versions.sh"
profile=${1:-test}
case "$profile" in
  demo | cpp | js | test) ;;
  *) echo "ensure-deps: unknown profile '$profile' (demo, cpp, js or test)" >&2; exit 2 ;;
esac
wants() { case " $1 " in *" $profile "*) return 0 ;; esac; return 1; }

missing=""
need_command() { command -v "$1" >/dev/null 2>&1 || missing="$missing $2"; }
need_file() { [ -e "$1" ] || missing="$missing $2"; }

need_command cmake cmake
need_command make make
if wants "demo js test"; then need_command em++ emscripten; fi
# The USGS DEMs (Jacksboro fault, topobathy) that the terrain tests, bench and demo read.
need_file /usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz \
  python-matplotlib-data
if wants "cpp test"; then
  need_command g++ g++
  need_file /usr/include/gtest/gtest.h libgtest-dev
  need_file /usr/include/gmpxx.h libgmp-dev
fi
if wants test; then
  need_command clang++ clang
  need_command clang-format clang-format
  need_command chromium chromium
fi

if [ -n "$missing" ]; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "ensure-deps: installing$missing" >&2
    export DEBIAN_FRONTEND=noninteractive
    # Another install may hold the dpkg lock for a while: wait for it rather than fail.
    apt_get() { apt-get -o DPkg::Lock::Timeout=600 "$@"; }
    # shellcheck disable=SC2086
    apt_get install -y $missing \
      || { apt_get update && apt_get install -y $missing; }
  else
    echo "ensure-deps: missing Debian packages:$missing. Run:" >&2
    echo "  sudo apt-get update && sudo apt-get install -y$missing" >&2
    exit 1
  fi
fi

# The oldest versions the project's files are written for: cmake_minimum_required in
# CMakeLists.txt, and the Node its dev tools declare (ESLint 10 and Vite 7: ^20.19, ^22.13 or
# 24 and later; Vite fails on Node 18, which lacks crypto.hash). The package itself runs on
# less: "engines" in package.json. A tool missing or older stops here, with what to do.
require_version() {  # tool, the command that prints its version, oldest version, advice
  found=$($2 2>/dev/null | first_version) || found=""
  [ -n "$found" ] && version_at_least "$found" "$3" && return 0
  echo "ensure-deps: $1 ${found:-is missing}${found:+ found}; $3 or later is needed: $4" >&2
  exit 1
}
require_version CMake "cmake --version" 3.16 \
  "Debian 11 and Ubuntu 20.04 have one, or pip install cmake"
require_version Node "node --version" 20.19 "ESLint and Vite declare ^20.19, ^22.13 or 24 and \
later; https://nodejs.org/en/download, or a distribution's package of such a version (with npm)"
node_version=$(node --version | first_version)
case $node_version in
  21.* | 23.* | 22.[0-9].* | 22.1[0-2].*)
    echo "ensure-deps: Node $node_version is outside what ESLint and Vite declare" \
      "(^20.19, ^22.13 or 24 and later); going on" >&2 ;;
esac

# npm ci when node_modules is missing or older than the lock file. Some registries answer
# without the other platforms' optional packages (rollup, esbuild), which npm ci then finds
# missing from the lock: npm install, which leaves the lock as it is, takes over. npm ci's
# errors come with its whole usage text: only their first lines are shown.
cd "$root"
if [ ! -f node_modules/.package-lock.json ] \
  || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  echo "ensure-deps: npm ci" >&2
  log=$(mktemp)
  if npm ci --no-audit --no-fund 2>"$log"; then
    cat "$log" >&2
  else
    grep '^npm error [^ ]' "$log" | head -n 3 >&2
    echo "ensure-deps: npm ci failed; npm install instead" >&2
    npm install --no-audit --no-fund
  fi
  rm -f "$log"
fi

wants "demo js test" || exit 0
# The wasm builds (glue and binary, and the threaded build's worker script) when any is
# missing or any source of them is newer: the core,
# the bindings, the CMake files and the build script. Folders count too (a file removed).
wasm=web/dist/geocdt.wasm
if [ ! -f "$wasm" ] || [ ! -f web/dist/geocdt.mjs ] || [ ! -f web/dist/geocdt-threads.wasm ] \
  || [ ! -f web/dist/geocdt-threads.mjs ] || [ ! -f web/dist/geocdt-threads.worker.js ] \
  || [ -n "$(find cpp bindings CMakeLists.txt scripts/build-wasm.sh -newer "$wasm" | head -n 1)" ]
then
  echo "ensure-deps: building the wasm (web/dist is missing or older than its sources)" >&2
  sh scripts/build-wasm.sh
fi
