#!/bin/sh
# Builds the WebAssembly module (geocdt.mjs + geocdt.wasm) into web/dist/, the folder that
# ships in the npm package. Users of the package never need Emscripten; this script does.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build="${GEOCDT_WASM_BUILD_DIR:-$root/build-wasm}"

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

emcmake cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target geocdt_wasm
# The glue and the wasm must come from the same link: copy both, then rename into place.
cp "$build/bindings/geocdt.mjs" "$root/web/dist/.geocdt.mjs.tmp"
cp "$build/bindings/geocdt.wasm" "$root/web/dist/.geocdt.wasm.tmp"
mv "$root/web/dist/.geocdt.wasm.tmp" "$root/web/dist/geocdt.wasm"
mv "$root/web/dist/.geocdt.mjs.tmp" "$root/web/dist/geocdt.mjs"
bytes=$(wc -c <"$root/web/dist/geocdt.wasm")
echo "build-wasm: web/dist/geocdt.mjs and web/dist/geocdt.wasm ($bytes bytes)" >&2
