#!/usr/bin/env bash
# Builds ksmc with AddressSanitizer + UndefinedBehaviorSanitizer
# (-DKSMC_SANITIZE=address,undefined, cmake/KsmcSanitize.cmake; -O1 -g1) in
# $KSMC_SANITIZE_BUILD_DIR (default build-asan) and runs tests under it. Any sanitizer report
# fails the test that triggered it (UBSan aborts, ASan exits non-zero, leaks included).
#   scripts/test-sanitize.sh [--ci] [extra ctest args]     e.g.  -R cli  or  -L mcmc
# Without --ci: the whole project and the whole suite. With --ci (what .ci/run does): the
# runtime and compiler tests, the toy domain and the bad-input suite, which fit CI's time
# budget (docs/reliability.md, "Sanitizers"): the targets in CI_TARGETS, the tests matching
# CI_TESTS. Prints the build and test times and the number of sanitizer reports.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${KSMC_SANITIZE_BUILD_DIR:-build-asan}"
SANITIZERS="${KSMC_SANITIZERS:-address,undefined}"
JOBS="${KSMC_JOBS:-$(nproc)}"
SCOPE=all
if [ "${1:-}" = "--ci" ]; then SCOPE=ci; shift; fi

# The CI scope: the Markov logic, MCMC, I/O, CLI and domain runtime, the compiler (front end,
# lowering, `ksmc infer`/`learn`/`fmt`/`check` end to end) and the bad-input suite on the toy
# domain (signals, whole-folder outputs, fault injection, readers).
CI_TARGETS=(ksmc ksmc_toy_domain test_mln test_runtime_io test_runtime_mcmc test_runtime_cli
            test_runtime_domain test_runtime_domain_cli test_frontend test_compiler_lower)
CI_TESTS='^(test_mln|test_runtime_io|test_runtime_mcmc|test_runtime_cli|test_runtime_domain|test_runtime_domain_cli|test_frontend|test_compiler_lower|infer_.*|learn_.*|alchemy_.*|diag_.*|fmt_roundtrip_.*|ksmc_list_passes|badinput)$'

start=$(date +%s)
mkdir -p "$BUILD_DIR"
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DKSMC_SANITIZE="$SANITIZERS" -DKSMC_BUILD_BENCH=OFF -DKSMC_FUZZ=OFF > "$BUILD_DIR/configure.log" 2>&1 \
  || { cat "$BUILD_DIR/configure.log"; exit 1; }
if [ "$SCOPE" = ci ]; then
  cmake --build "$BUILD_DIR" -j "$JOBS" --target "${CI_TARGETS[@]}"
else
  cmake --build "$BUILD_DIR" -j "$JOBS"
fi
built=$(date +%s)

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/scripts/lsan.supp}"
cd "$BUILD_DIR"
ctest_args=(--output-on-failure -j "$JOBS")
[ "$SCOPE" = ci ] && ctest_args+=(-R "$CI_TESTS")
set +e
ctest "${ctest_args[@]}" "$@" 2>&1 | tee ctest-sanitize.log
status=${PIPESTATUS[0]}
set -e
done_at=$(date +%s)
reports=$(grep -cE 'ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:' ctest-sanitize.log || true)
summary=$(grep -E 'tests passed|tests failed' ctest-sanitize.log | tail -1)
echo "test-sanitize.sh ($SCOPE): $SANITIZERS: build $((built - start)) s, tests $((done_at - built)) s; ${summary:-no tests ran}; sanitizer reports: $reports"
exit "$status"
