#!/bin/sh
# The thread tests (tests/cpp/threads_test.cpp) under ThreadSanitizer: strips write one shared
# set of slot arrays from several threads, each its own part; a race here fails the run.
# Needs clang and its sanitizer runtimes (Debian: clang, libclang-rt-N-dev; run-fuzz.sh
# installs both). Environment: GEOCDT_TSAN_BUILD (build directory, default build-tsan),
# GEOCDT_TSAN_STEP (build: configure and build, then stop; run: run what was built; unset:
# both).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${GEOCDT_TSAN_BUILD:-$root/build-tsan}
step=${GEOCDT_TSAN_STEP:-}
case $step in
  '' | build | run) ;;
  *) echo "run-tsan: GEOCDT_TSAN_STEP must be build or run, got '$step'" >&2
    exit 2 ;;
esac
if [ "$step" != run ]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS=-fsanitize=thread -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=thread \
    -DGEOCDT_BUILD_BENCH=OFF -DGEOCDT_UNITY_BUILD=ON >/dev/null
  cmake --build "$build" -j2 --target threads_test
fi
[ "$step" = build ] && exit 0
# halt_on_error: the first report fails the run. The extreme-coordinates test is left out:
# its exact-arithmetic fallbacks take minutes under the sanitizer, and it adds no thread.
TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" \
  "$build/tests/threads_test" --gtest_filter='-*TinyAndHuge*' --gtest_brief=1
echo "run-tsan: no data race in the thread tests" >&2
