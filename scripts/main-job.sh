#!/usr/bin/env bash
# The main job on the bundled examples: check both domain files, show their lowered
# knowledge bases, then (where the domain binaries are built) map the bundled simulated
# floor plan, analyse the bundled table-top scene and fit line segments to the bundled 2D
# point cloud (examples/segments). Prints where pictures, JSON and each run's report.html
# (open it in a browser) went.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${KSMC_BUILD_DIR:-build}"
OUT_DIR="${KSMC_OUT_DIR:-out}"
BIN="$BUILD_DIR/bin"

echo "== ksmc check domains/*.ksm"
"$BIN/ksmc" check domains/*.ksm

echo "== ksmc infer domains/tabletop.ksm on the seed's 7-object example (exact)"
"$BIN/ksmc" infer domains/tabletop.ksm --evidence tests/compiler/infer/seed_example_exact/evidence.db \
  --method exact --query falseEst,hidden

mkdir -p "$OUT_DIR"
if [ -x "$BIN/indoor" ]; then
  echo "== indoor: examples/indoor/sim_office.yaml"
  "$BIN/indoor" examples/indoor/sim_office.yaml --out "$OUT_DIR/indoor" --seed 1 --trace
  echo "indoor results: $OUT_DIR/indoor/world.json, overlay.png, labels.png, trace.png, summary.json"
  echo "indoor report: $OUT_DIR/indoor/report.html"
else
  echo "== indoor: bin/indoor is not built in this checkout (no stdlib kit); skipped"
fi
if [ -x "$BIN/tabletop" ]; then
  echo "== tabletop: examples/tabletop/seed_example.json"
  "$BIN/tabletop" examples/tabletop/seed_example.json --out "$OUT_DIR/tabletop" --seed 1 --trace
  echo "tabletop results: $OUT_DIR/tabletop/scene_graph.json, graph.png, overlay.png, summary.json"
  echo "tabletop report: $OUT_DIR/tabletop/report.html"
else
  echo "== tabletop: bin/tabletop is not built in this checkout (no stdlib kit); skipped"
fi
if [ -x "$BIN/segments" ]; then
  echo "== segments: examples/segments/room.txt (domain written only in examples/segments/segments.ksm)"
  "$BIN/ksmc" check examples/segments/segments.ksm
  "$BIN/segments" examples/segments/room.txt --out "$OUT_DIR/segments" --seed 1 --trace
  echo "segments results: $OUT_DIR/segments/segments.json, overlay.png, summary.json"
  echo "segments report: $OUT_DIR/segments/report.html"
else
  echo "== segments: bin/segments is not built in this checkout (no stdlib kit); skipped"
fi
