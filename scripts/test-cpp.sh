#!/bin/sh
# `npm run test:cpp`: the native build and its tests (the GoogleTest suites, the fuzz corpus
# replayed, the real-data tests): what it lacks first (scripts/ensure-deps.sh cpp), then
# configure, build and ctest in build/. A test whose dependencies are missing fails the
# configure instead of being left out. Arguments go to ctest:
#
#   npm run test:cpp -- -R Constraints     # the tests whose names match
set -eu
cd "$(dirname "$0")/.."
sh scripts/ensure-deps.sh cpp
jobs=$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 2)
cmake -S . -B build -DGEOCDT_BUILD_TESTS=ON -DGEOCDT_REQUIRE_ALL_TESTS=ON -DGEOCDT_UNITY_BUILD=ON
cmake --build build -j "$jobs"
cd build
ctest --output-on-failure -j "$jobs" "$@"
