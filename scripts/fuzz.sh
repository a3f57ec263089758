#!/usr/bin/env bash
# Fuzzes ksmc's readers with libFuzzer (compiler/fuzz, docs/reliability.md).
#   scripts/fuzz.sh [seconds] [target ...]     seconds per target (default 60); default: all
# Targets: fuzz_frontend fuzz_ksm_includes fuzz_db fuzz_scene fuzz_map fuzz_mln fuzz_cloud.
# Configures a separate clang build of just the fuzz targets (compiler/fuzz/CMakeLists.txt,
# ASan + UBSan) in $KSMC_FUZZ_BUILD_DIR (default build-fuzz). Each target starts from its
# seed corpus in compiler/fuzz/corpus/<target> plus the repository's own inputs of that
# kind, keeps what it finds in $BUILD_DIR/corpus/<target>, and prints one summary line:
#   fuzz <target>: <runs> runs in <s> s, cov <edges> ft <features>, corpus <n> (<max> B max), peak <MB> MB, <result>
# Exits non-zero when any target finds a crash, leak, timeout or out-of-memory.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT="$PWD"
SECONDS_TO_RUN="${1:-60}"
shift || true
TARGETS=("$@")
[ ${#TARGETS[@]} -eq 0 ] && TARGETS=(fuzz_frontend fuzz_ksm_includes fuzz_db fuzz_scene fuzz_map fuzz_mln fuzz_cloud)
BUILD_DIR="${KSMC_FUZZ_BUILD_DIR:-build-fuzz}"
JOBS="${KSMC_JOBS:-2}"
CXX_BIN="${KSMC_FUZZ_CXX:-clang++}"

command -v "$CXX_BIN" >/dev/null || { echo "fuzz.sh: $CXX_BIN not found"; exit 1; }
mkdir -p "$BUILD_DIR"
# Configured every time (cheap; it picks up new targets; the ANTLR shim header is rewritten
# only when its text changes, so nothing recompiles).
cmake -S compiler/fuzz -B "$BUILD_DIR" -DCMAKE_CXX_COMPILER="$CXX_BIN" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  > "$BUILD_DIR/configure.log" 2>&1 || { cat "$BUILD_DIR/configure.log"; exit 1; }
cmake --build "$BUILD_DIR" --target "${TARGETS[@]}" -j "$JOBS" > "$BUILD_DIR/build.log" 2>&1 \
  || { tail -50 "$BUILD_DIR/build.log"; exit 1; }

# The repository's own inputs of each kind, added to the checked-in seeds.
repo_seeds() {
  case "$1" in
    fuzz_frontend) ls domains/*.ksm stdlib/*.ksm tests/frontend/fmt/*.ksm tests/frontend/diag/*/input.ksm 2>/dev/null ;;
    fuzz_ksm_includes) ls examples/*/*.ksm 2>/dev/null ;;
    fuzz_db) ls tests/compiler/infer/*/evidence.db 2>/dev/null ;;
    fuzz_scene) ls examples/tabletop/*.json tests/tabletop/data/*.json 2>/dev/null ;;
    fuzz_map) ls examples/indoor/*.pgm 2>/dev/null ;;
    fuzz_mln) find examples/mln tests/compiler/alchemy -name '*.mln' 2>/dev/null | sort ;;
    fuzz_cloud) find examples tests -name '*.ply' -o -name '*.pcd' 2>/dev/null | sort ;;
  esac
}
# Largest input libFuzzer may grow to: above the largest seed, so inputs can grow.
max_len() {
  case "$1" in
    fuzz_map) echo 1048576 ;;   # an image of up to ~1000x1000 cells
    fuzz_scene|fuzz_cloud) echo 262144 ;;   # fuzz_cloud: ~10,000 binary points
    *) echo 65536 ;;
  esac
}

status=0
for t in "${TARGETS[@]}"; do
  CORPUS="$BUILD_DIR/corpus/$t"
  SEEDS="$BUILD_DIR/seeds/$t"
  ARTIFACTS="$BUILD_DIR/artifacts/$t/"
  mkdir -p "$CORPUS" "$SEEDS" "$ARTIFACTS"
  cp compiler/fuzz/corpus/"$t"/* "$SEEDS"/ 2>/dev/null || true
  for f in $(repo_seeds "$t"); do cp "$f" "$SEEDS/$(echo "$f" | tr '/' '_')"; done
  if [ "$t" = fuzz_ksm_includes ]; then  # each stdlib file, included by a two-file input
    for f in stdlib/*.ksm; do
      printf 'domain d;\ninclude "lib.ksm";\n//@file lib.ksm\n' | cat - "$f" > "$SEEDS/includes_$(basename "$f")"
    done
  fi
  LOG="$BUILD_DIR/fuzz-$t.log"
  start=$(date +%s)
  set +e
  ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
  "$BUILD_DIR/$t" "$CORPUS" "$SEEDS" \
    -max_total_time="$SECONDS_TO_RUN" -max_len="$(max_len "$t")" -len_control=0 -timeout=10 \
    -rss_limit_mb=2048 -malloc_limit_mb=2048 -seed=1 -print_final_stats=1 -artifact_prefix="$ARTIFACTS" \
    > "$LOG" 2>&1
  rc=$?
  set -e
  took=$(( $(date +%s) - start ))
  last=$(grep -E '^#[0-9]+[[:space:]]+(DONE|pulse|NEW|REDUCE|INITED)' "$LOG" | tail -1 || true)
  runs=$(grep -E '^stat::number_of_executed_units' "$LOG" | awk '{print $2}')
  peak=$(grep -E '^stat::peak_rss_mb' "$LOG" | awk '{print $2}')
  cov=$(echo "$last" | sed -nE 's/.*cov: ([0-9]+).*/\1/p')
  ft=$(echo "$last" | sed -nE 's/.*ft: ([0-9]+).*/\1/p')
  files=$(ls "$CORPUS" | wc -l)
  biggest=$(find "$CORPUS" -type f -printf '%s\n' | sort -n | tail -1)
  result="no crash"
  [ "$rc" -ne 0 ] && result="FAILED (libFuzzer exit $rc; log $LOG; artifacts in $ARTIFACTS)"
  echo "fuzz $t: ${runs:-?} runs in ${took} s, cov ${cov:-?} ft ${ft:-?}, corpus $files (${biggest:-0} B max), peak ${peak:-?} MB, $result"
  if [ "$rc" -ne 0 ]; then
    tail -40 "$LOG"
    status=$rc
  fi
done
exit "$status"
