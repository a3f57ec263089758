#!/usr/bin/env bash
# The main job on the bundled examples. Grows as the domain binaries arrive.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${KSMC_BUILD_DIR:-build}"
echo "== ksmc check domains/*.ksm"
"$BUILD_DIR/bin/ksmc" check domains/*.ksm
