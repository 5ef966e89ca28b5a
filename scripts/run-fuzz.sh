#!/bin/sh
# Builds the libFuzzer targets (clang, ASan + UBSan) in a build directory of their own and
# runs each for a bounded time. Exits non-zero on any crash, sanitizer report, invariant
# failure or hang; the input that caused it is kept in <build>/artifacts/.
#
#   scripts/run-fuzz.sh [seconds-per-target]     (default 60)
#
# Environment: GEOCDT_FUZZ_BUILD (build directory, default build-fuzz),
# GEOCDT_FUZZ_TARGETS (default: every target of tests/fuzz/CMakeLists.txt, which the
# configure step lists in <build>/fuzz_targets.txt),
# GEOCDT_FUZZ_SEED and GEOCDT_FUZZ_RUNS (a fixed seed and number of inputs: as much fuzzing on
# any machine, as long as the seconds do not cut it short; not the very same inputs, see
# tests/fuzz/README.md), GEOCDT_FUZZ_TIMEOUT (seconds one input may take, default 20;
# fuzz_strips triangulates 33,000 points a few times, and fuzz_refine's refinements of points
# spanning the whole double range test in big integers: 60), GEOCDT_FUZZ_STEP (build:
# configure and build the targets, then stop; run: run targets built before, without touching
# the build directory, so that runs of single targets can go side by side; unset: both).
# Replay one input:  build-fuzz/tests/fuzz/fuzz_polylines FILE   (GEOCDT_FUZZ_PRINT=1 prints it)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
build=${GEOCDT_FUZZ_BUILD:-$root/build-fuzz}
targets=${GEOCDT_FUZZ_TARGETS:-}

# (0 would mean no limit to libFuzzer.)
case $seconds in
  '' | *[!0-9]* | 0) echo "run-fuzz: seconds must be a positive whole number, got '$seconds'" >&2
    exit 2 ;;
esac

install_or_explain() {
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "run-fuzz: installing $*" >&2
    DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y "$@" \
      || { apt-get -o DPkg::Lock::Timeout=600 update \
           && DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y "$@"; }
  else
    echo "run-fuzz: missing Debian packages: $*. Run:" >&2
    echo "  sudo apt-get install -y $*" >&2
    exit 1
  fi
}

step=${GEOCDT_FUZZ_STEP:-}
case $step in
  '' | build | run) ;;
  *) echo "run-fuzz: GEOCDT_FUZZ_STEP must be build or run, got '$step'" >&2
    exit 2 ;;
esac

if [ "$step" != run ]; then
  command -v cmake >/dev/null 2>&1 || install_or_explain cmake
  command -v clang++ >/dev/null 2>&1 || install_or_explain clang

  # libFuzzer's runtime is not in every clang install: Debian ships it in libclang-rt-N-dev.
  probe=$(mktemp -d)
  trap 'rm -rf "$probe"' EXIT
  printf '%s\n' 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) {' \
    '  return 0;' '}' >"$probe/probe.cpp"
  if ! clang++ -fsanitize=fuzzer,address,undefined "$probe/probe.cpp" -o "$probe/probe" \
    2>"$probe/log"; then
    major=$(clang++ -dumpversion | cut -d. -f1)
    install_or_explain "libclang-rt-$major-dev"
    clang++ -fsanitize=fuzzer,address,undefined "$probe/probe.cpp" -o "$probe/probe" || {
      echo "run-fuzz: clang++ still cannot link libFuzzer" >&2
      exit 1
    }
  fi

  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DGEOCDT_BUILD_FUZZ=ON -DGEOCDT_BUILD_TESTS=OFF -DGEOCDT_BUILD_BENCH=OFF \
    -DGEOCDT_UNITY_BUILD=ON >/dev/null
fi
if [ -z "$targets" ]; then
  [ -f "$build/fuzz_targets.txt" ] || {
    echo "run-fuzz: $build has no fuzz_targets.txt: build the targets first (GEOCDT_FUZZ_STEP=build)" >&2
    exit 1
  }
  targets=$(cat "$build/fuzz_targets.txt")
fi
if [ "$step" != run ]; then
  cmake --build "$build" -j2 --target $targets
fi
[ "$step" = build ] && exit 0

status=0
for target in $targets; do
  # New inputs go to a corpus in the build directory; the checked-in seeds are read only.
  corpus=$build/corpus/$target
  mkdir -p "$corpus" "$build/artifacts"
  timeout=${GEOCDT_FUZZ_TIMEOUT:-20}
  case $target in fuzz_strips | fuzz_refine) timeout=${GEOCDT_FUZZ_TIMEOUT:-60} ;; esac
  echo "run-fuzz: $target for ${seconds}s" >&2
  # GEOCDT_FUZZ_SEED and GEOCDT_FUZZ_RUNS fix how much a run fuzzes (CI uses them).
  if ! "$build/tests/fuzz/$target" "$corpus" "$root/tests/fuzz/corpus/$target" \
      -max_total_time="$seconds" ${GEOCDT_FUZZ_SEED:+-seed=$GEOCDT_FUZZ_SEED} \
      ${GEOCDT_FUZZ_RUNS:+-runs=$GEOCDT_FUZZ_RUNS} -max_len=4096 -timeout="$timeout" -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$build/artifacts/$target-" \
      2>"$build/$target.log"; then
    status=1
    tail -n 60 "$build/$target.log" >&2
    echo "run-fuzz: $target FAILED" >&2
    grep -o 'Test unit written to .*' "$build/$target.log" >&2 || true
  else
    grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb)|^Done' "$build/$target.log" >&2 \
      || true
  fi
done
exit $status
