#!/bin/sh
# tests/indoor_io/rerender_matches_run.sh INDOOR RENDER SHARED_DIR OUT_DIR
# ksmc-render-world redraws a run's labels.png, segmentation.png and overlay.png byte for byte: it
# reads the map as the run saw it (world.json map.cleanup: specks cleared, solid interiors
# unexplained). Freiburg79_scan has five specks; drawn over the raw map, one of them parts a
# corridor join and the redrawn segmentation differs from the run's. Exit 77 (skipped) when the
# shared data folder is absent.
set -eu
indoor=$1 render=$2 shared=$3 out=$4
map=$shared/data/maps/bormann_ipa/test_maps/Freiburg79_scan.png
if [ ! -f "$map" ]; then
  echo "skipped: $map not found (the shared data folder is absent)"
  exit 77
fi
rm -rf "$out"
"$indoor" "$map" --resolution 0.05 --out "$out/run" --seed 1 --iterations 3000 --quiet
"$render" "$map" "$out/run/world.json" "$out/redraw" --resolution 0.05
for f in labels.png segmentation.png overlay.png; do
  cmp "$out/run/$f" "$out/redraw/$f"
done
echo "redrawn images match the run's"
