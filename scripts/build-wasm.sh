#!/bin/sh
# Builds the WebAssembly modules into web/dist/, the folder that ships in the npm package:
# geocdt.mjs + geocdt.wasm (one thread), and geocdt-threads.mjs + .wasm + .worker.js (the
# threaded build, for init({ threads })). Users of the package never need Emscripten; this
# script does.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build="${GEOCDT_WASM_BUILD_DIR:-$root/build-wasm}"
threads_build="${build}-threads"

if ! command -v emcmake >/dev/null 2>&1; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "build-wasm: Emscripten is missing; installing Debian's package" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get install -y emscripten || { apt-get update && apt-get install -y emscripten; }
  else
    echo "build-wasm: Emscripten (emcmake, em++) is missing." \
      "Install it, then run npm run build:" >&2
    echo "  sudo apt-get update && sudo apt-get install -y emscripten    # Debian, Ubuntu" >&2
    echo "  or install the emsdk and source its emsdk_env.sh, so that emcmake is on PATH" >&2
    exit 1
  fi
fi

# Emscripten 3.1.6 (Debian 12's package) is the version the build and web/ are made for. From
# 3.1.52 on, the threaded build's worker script is no longer geocdt-threads.worker.js (named
# .worker.mjs in 3.1.52, folded into the glue from 3.1.58: Emscripten's ChangeLog), which
# web/ loads. Other versions may work: said, then tried.
. "$root/scripts/versions.sh"
emscripten=$(emcc --version 2>/dev/null | first_version)
if version_at_least "$emscripten" 3.1.52; then
  echo "build-wasm: Emscripten $emscripten found; from 3.1.52 on it no longer writes the" \
    "threaded build's worker script that web/ loads. Use 3.1.6, Debian 12's package" \
    "(apt-get install emscripten), or the emsdk's (emsdk install 3.1.6 &&" \
    "emsdk activate 3.1.6, then source its emsdk_env.sh)." >&2
  exit 1
elif [ "$emscripten" != 3.1.6 ]; then
  echo "build-wasm: Emscripten ${emscripten:-of unknown version} found; the build is known" \
    "to work with 3.1.6 (Debian 12's package). Trying it; if the build or the JS tests" \
    "fail, use 3.1.6 (emsdk install 3.1.6 && emsdk activate 3.1.6)." >&2
fi

# Debian's emscripten runs its JS tools with Debian's node modules (acorn), which a node
# installed elsewhere does not search by itself.
if [ -d /usr/share/nodejs/acorn ]; then
  export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}"
fi

# Two builds at once in one folder would mix a glue with the other's wasm: take turns.
mkdir -p "$build" "$root/web/dist"
if command -v flock >/dev/null 2>&1; then
  exec 9>"$build/.build-lock"
  flock 9
fi

emcmake cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DGEOCDT_UNITY_BUILD=ON \
  >/dev/null
cmake --build "$build" -j2 --target geocdt_wasm
emcmake cmake -S "$root" -B "$threads_build" -DCMAKE_BUILD_TYPE=Release -DGEOCDT_UNITY_BUILD=ON \
  -DGEOCDT_WASM_THREADS=ON >/dev/null
# (Emscripten warns that growing shared memory slows JS access to it: the binding reads the
# heap once per output array.)
cmake --build "$threads_build" -j2 --target geocdt_wasm 2>&1 | grep -v pthreads-mem-growth >&2
# The threaded glue starts its pool with new Worker(new URL("geocdt-threads.worker.js",
# import.meta.url)). Bundlers take that form as a worker to bundle, and Vite's default
# worker format cannot bundle one that imports the glue back (every Vite app using geocdt
# would fail to build). Written as new Worker((0, new URL(...))), the script is an asset
# copied as it is, as the glue expects; the build stops if the form ever changes.
glue="$threads_build/bindings/geocdt-threads.mjs"
pool='new Worker(new URL("geocdt-threads.worker.js",import.meta.url))'
if ! grep -qF "$pool" "$glue" && ! grep -qF 'new Worker((0,new URL(' "$glue"; then
  echo "build-wasm: the threaded glue no longer starts its workers as expected: $pool" >&2
  exit 1
fi
sed -i 's|new Worker(new URL("geocdt-threads.worker.js",import.meta.url))|new Worker((0,new URL("geocdt-threads.worker.js",import.meta.url)))|' "$glue"
# A glue and its wasm must come from the same link: copy each set, then rename into place.
install_files() {
  for file in "$@"; do cp "$file" "$root/web/dist/.$(basename "$file").tmp"; done
  for file in "$@"; do
    mv "$root/web/dist/.$(basename "$file").tmp" "$root/web/dist/$(basename "$file")"
  done
}
install_files "$build/bindings/geocdt.wasm" "$build/bindings/geocdt.mjs"
install_files "$threads_build/bindings/geocdt-threads.wasm" \
  "$threads_build/bindings/geocdt-threads.worker.js" "$threads_build/bindings/geocdt-threads.mjs"
bytes=$(wc -c <"$root/web/dist/geocdt.wasm")
threaded=$(wc -c <"$root/web/dist/geocdt-threads.wasm")
echo "build-wasm: web/dist/geocdt.{mjs,wasm} ($bytes bytes)," \
  "geocdt-threads.{mjs,wasm,worker.js} ($threaded bytes)" >&2
