#!/usr/bin/env bash
# scripts/batch.sh BIN INPUT... --out DIR [-j N] [-- ARGS...]
# Runs a domain binary over many inputs in parallel and writes DIR/batch.csv and batch.md
# (one row per input); see tools/batch/batch.h and docs/scale.md.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
tool="${KSMC_BUILD_DIR:-$here/build}/bin/ksmc-batch"
[ -x "$tool" ] || tool=$(command -v ksmc-batch || true)
if [ -z "$tool" ]; then
  echo "scripts/batch.sh: ksmc-batch not found; run scripts/build.sh first" >&2
  exit 2
fi
exec "$tool" "$@"
