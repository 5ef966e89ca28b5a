#!/bin/sh
# `npm test`: everything, in order, stopping at the first failure.
set -eu
cd "$(dirname "$0")/.."
sh scripts/ensure-deps.sh  # Debian packages, npm dependencies, the wasm if it is stale
npm run --silent lint      # ESLint, the layers of cpp/src, clang-format on the C++
sh scripts/test-cpp.sh     # native build + ctest (npm run test:cpp)
sh scripts/test-js.sh tests/js/ tests/demo/  # node and browser tests (npm run test:js)
