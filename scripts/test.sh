#!/usr/bin/env bash
# Quick start, command 2: build (if needed) and run every test.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${KSMC_BUILD_DIR:-build}"
scripts/build.sh -DKSMC_FUZZ="${KSMC_FUZZ:-ON}" -DKSMC_FUZZ_SECONDS="${KSMC_FUZZ_SECONDS:-60}"
cd "$BUILD_DIR"
ctest --output-on-failure -j "${KSMC_JOBS:-$(nproc)}"
