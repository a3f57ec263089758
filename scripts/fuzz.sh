#!/usr/bin/env bash
# Fuzzes the ksmc front end (parse + build + check + fmt round trip) with libFuzzer.
#   scripts/fuzz.sh [seconds]      (default 60)
# Configures a separate clang build of just the fuzz target (compiler/fuzz/CMakeLists.txt)
# in $KSMC_FUZZ_BUILD_DIR (default build-fuzz), seeds the corpus with the repo's .ksm
# files, runs for the given time and prints libFuzzer's summary. Exits non-zero when
# libFuzzer finds a crash, leak or timeout.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT="$PWD"
SECONDS_TO_RUN="${1:-60}"
BUILD_DIR="${KSMC_FUZZ_BUILD_DIR:-build-fuzz}"
JOBS="${KSMC_JOBS:-2}"
CXX_BIN="${KSMC_FUZZ_CXX:-clang++}"

command -v "$CXX_BIN" >/dev/null || { echo "fuzz.sh: $CXX_BIN not found"; exit 1; }
mkdir -p "$BUILD_DIR"
cmake -S compiler/fuzz -B "$BUILD_DIR" -DCMAKE_CXX_COMPILER="$CXX_BIN" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  > "$BUILD_DIR/configure.log" 2>&1 || { cat "$BUILD_DIR/configure.log"; exit 1; }
cmake --build "$BUILD_DIR" --target fuzz_frontend -j "$JOBS" > "$BUILD_DIR/build.log" 2>&1 \
  || { tail -50 "$BUILD_DIR/build.log"; exit 1; }

CORPUS="$BUILD_DIR/corpus"
SEEDS="$BUILD_DIR/seeds"
mkdir -p "$CORPUS" "$SEEDS" "$BUILD_DIR/artifacts"
for f in domains/*.ksm stdlib/*.ksm tests/frontend/fmt/*.ksm tests/frontend/diag/*/input.ksm; do
  [ -f "$f" ] && cp "$f" "$SEEDS/$(echo "$f" | tr '/' '_')"
done

LOG="$BUILD_DIR/fuzz.log"
set +e
ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1" \
"$BUILD_DIR/fuzz_frontend" "$CORPUS" "$SEEDS" \
  -max_total_time="$SECONDS_TO_RUN" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
  -seed=1 -print_final_stats=1 -artifact_prefix="$BUILD_DIR/artifacts/" > "$LOG" 2>&1
STATUS=$?
set -e
# libFuzzer's summary: the last status line (#N DONE/... cov: ... exec/s) and final stats.
grep -E '^#[0-9]+[[:space:]]+(DONE|pulse|NEW|REDUCE)' "$LOG" | tail -1 || true
grep -E '^(Done|stat::number_of_executed_units|stat::peak_rss_mb)' "$LOG" || true
if [ "$STATUS" -ne 0 ]; then
  echo "fuzz.sh: libFuzzer exited with $STATUS; log tail:"
  tail -60 "$LOG"
  exit "$STATUS"
fi
echo "fuzz.sh: no crash in ${SECONDS_TO_RUN}s"
