#!/bin/sh
# `npm test`: everything, in order, stopping at the first failure.
set -eu
cd "$(dirname "$0")/.."
sh scripts/ensure-deps.sh  # Debian packages, npm dependencies, the wasm if it is stale
npm run --silent lint      # ESLint, then clang-format --dry-run on the C++
cmake -S . -B build -DGEOCDT_BUILD_TESTS=ON
cmake --build build -j2
ctest --test-dir build --output-on-failure --no-tests=error -j2
sh scripts/build-wasm.sh   # a no-op unless the sources changed
node --test tests/js/ tests/demo/
