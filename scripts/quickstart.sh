#!/usr/bin/env bash
# Quick start, command 1: install Debian packages, build, run the main job on the bundled examples.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
scripts/main-job.sh
