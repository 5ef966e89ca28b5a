#!/bin/sh
# Installs what a fresh Debian machine lacks, then the npm dev dependencies, then builds the
# wasm when web/dist is missing or older than its sources. As root it installs Debian
# packages; otherwise it prints the exact command to run and fails.
#
#   sh scripts/ensure-deps.sh demo   # what `npm run demo` needs: CMake, make, Emscripten,
#                                    # and the USGS elevation models of the terrain page
#   sh scripts/ensure-deps.sh        # what `npm test` needs: those, the native compilers,
#                                    # GoogleTest, GMP, clang-format and Chromium
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
profile=${1:-test}
case "$profile" in
  demo | test) ;;
  *) echo "ensure-deps: unknown profile '$profile' (demo or test)" >&2; exit 2 ;;
esac

missing=""
need_command() { command -v "$1" >/dev/null 2>&1 || missing="$missing $2"; }
need_file() { [ -e "$1" ] || missing="$missing $2"; }

need_command cmake cmake
need_command make make
need_command em++ emscripten
# The USGS DEMs (Jacksboro fault, topobathy) that the terrain tests, bench and demo read.
need_file /usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz \
  python-matplotlib-data
if [ "$profile" = test ]; then
  need_command g++ g++
  need_command clang++ clang
  need_command clang-format clang-format
  need_command chromium chromium
  need_file /usr/include/gtest/gtest.h libgtest-dev
  need_file /usr/include/gmpxx.h libgmp-dev
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
