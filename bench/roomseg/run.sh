#!/usr/bin/env bash
# bench/roomseg/run.sh INDOOR_BIN SCORE_BIN OUT_DIR [ITERATIONS] [-- extra indoor flags]
# Runs the indoor binary on the 20 maps of the Bormann et al. benchmark
# (../shared/data/maps/bormann_ipa/test_maps), unfurnished and furnished, and scores each
# run's segmentation.png (labels.png when absent) with roomseg_score against the map's
# ground truth. Prints per-map rows and the per-map averages beside the published ones.
# Environment: SEED (default 1), ROOMSEG_MAPS ("map1 map2 ...": a subset of the 20),
# ROOMSEG_VARIANTS (default "unfurnished furnished"; also "trashbins" and "furnished_trashbins",
# the benchmark's two other map images, which share the ground truth), KSMC_SHARED_DIR (where
# ../shared is). A map whose segmentation cannot be scored is left out with a row saying why
# (lab_b_scan_furnitures_trashbins.png is 649 x 243, its ground truth 974 x 365); so is a
# missing image (lab_d_scan has no furnished trashbins image).
# The same maps turned and rescaled: transforms.sh (docs/indoor_transforms.md).
set -euo pipefail
bin=$1; scorer=$2; out=$3; iters=${4:-10000}
shift $(( $# >= 4 ? 4 : $# ))
[ "${1:-}" = "--" ] && shift
here=$(cd "$(dirname "$0")" && pwd)
. "$here/maps.sh"
mkdir -p "$out"
printf '| map | variant | R | P | IoU | rooms | segments | seconds |\n|---|---|---|---|---|---|---|---|\n'
read -r -a variants <<< "${ROOMSEG_VARIANTS:-unfurnished furnished}"
for variant in "${variants[@]}"; do
  suffix=$(variant_suffix "$variant")
  scores=()
  for m in "${names[@]}"; do
    img=$maps/$m$suffix.png
    gt=$maps/${m}_gt_segmentation.png
    [ -f "$img" ] && [ -f "$gt" ] || { echo "| $m | $variant | missing input | | | | | |"; continue; }
    dir=$out/$variant/$m
    mkdir -p "$out/$variant"
    t0=$(date +%s.%N)
    if ! "$bin" "$img" --resolution 0.05 --out "$dir" --seed "${SEED:-1}" --iterations "$iters" --quiet "$@" > "$dir.log" 2>&1; then
      echo "| $m | $variant | run failed (see $dir.log) | | | | | |"; continue
    fi
    t1=$(date +%s.%N)
    seg=$dir/segmentation.png
    if [ ! -f "$seg" ]; then seg=$dir/labels.png; echo "note: $m ($variant) scored labels.png: the binary wrote no segmentation.png"; fi
    if ! line=$("$scorer" "$gt" "$seg" 2>&1); then
      echo "| $m | $variant | not scored: ${line//|/:} | | | | | |"; continue
    fi
    echo "$line $t0 $t1" | awk -v m="$m" -v v="$variant" \
      '{printf "| %s | %s | %.1f | %.1f | %.1f | %s | %s | %.1f |\n", m, v, 100*$1, 100*$2, 100*$3, $4, $5, $7-$6}'
    scores+=("$line")
  done
  if [ "${#scores[@]}" -gt 0 ]; then
    printf '%s\n' "${scores[@]}" | awk -v v="$variant" \
      '{r+=$1; p+=$2; i+=$3; n++} END {printf "| **average (%d maps)** | %s | **%.1f** | **%.1f** | **%.1f** | | | |\n", n, v, 100*r/n, 100*p/n, 100*i/n}'
  fi
done
cat <<'TABLE'
| Voronoi (published, Bormann et al. 2016) | unfurnished | 95.0 | 94.8 | | | | |
| Voronoi (published) | furnished | 86.6 | 94.5 | | | | |
| morphological (published) | unfurnished | 98.1 | 88.5 | | | | |
| morphological (published) | furnished | 84.6 | 90.5 | | | | |
TABLE
