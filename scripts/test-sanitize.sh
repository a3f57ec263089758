#!/usr/bin/env bash
# Opt-in: builds ksmc with AddressSanitizer + UndefinedBehaviorSanitizer
# (-DKSMC_SANITIZE=address,undefined, cmake/KsmcSanitize.cmake) in $KSMC_SANITIZE_BUILD_DIR
# (default build-asan) and runs the whole test suite under it. Any sanitizer report fails
# the test that triggered it (UBSan aborts, ASan exits non-zero, leaks included).
#   scripts/test-sanitize.sh [extra ctest args]      e.g.  -R cli  or  -L mcmc
# Prints the build and test times. Benchmarks are not built (KSMC_BUILD_BENCH=OFF).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${KSMC_SANITIZE_BUILD_DIR:-build-asan}"
SANITIZERS="${KSMC_SANITIZERS:-address,undefined}"
JOBS="${KSMC_JOBS:-$(nproc)}"

start=$(date +%s)
KSMC_BUILD_DIR="$BUILD_DIR" KSMC_JOBS="$JOBS" scripts/build.sh -DKSMC_SANITIZE="$SANITIZERS" -DKSMC_BUILD_BENCH=OFF \
  -DKSMC_FUZZ=OFF
built=$(date +%s)

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/scripts/lsan.supp}"
cd "$BUILD_DIR"
set +e
ctest --output-on-failure -j "$JOBS" "$@" 2>&1 | tee ctest-sanitize.log
status=${PIPESTATUS[0]}
set -e
done_at=$(date +%s)
reports=$(grep -cE 'ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:' ctest-sanitize.log || true)
echo "test-sanitize.sh: $SANITIZERS: build $((built - start)) s, tests $((done_at - built)) s, sanitizer reports: $reports"
exit "$status"
