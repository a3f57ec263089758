#!/usr/bin/env bash
# bench/roomseg/transforms.sh INDOOR_BIN SCORE_BIN OUT_DIR [ITERATIONS (default auto)] [-- extra indoor flags]
# The Bormann et al. maps (ROOMSEG_VARIANT, unfurnished by default) turned, rescaled or
# speckled: does the segmentation hold when the building is not aligned with the image axes,
# the grid is coarser or finer than 0.05 m, or the free space holds specks? transform_map.py writes each transformed map with its ground truth (rooms moved as
# regions); the indoor binary runs on it at the transformed resolution, and roomseg_score
# scores segmentation.png. Prints per-map rows (R / P / IoU, seconds) and per-transform averages.
# Environment: SEED (default 1), TRANSFORMS (default "none rot20 rot45 half double"; any rotN
# and speckleN, and steps joined by +, e.g. rot20+speckle10: transform_map.py),
# ROOMSEG_VARIANT (default unfurnished; or furnished, ...),
# ROOMSEG_MAPS ("map1 map2 ...": a subset of the 20), KSMC_SHARED_DIR (where ../shared is),
# PYTHON (default /usr/bin/python3, with numpy, scipy and PIL).
set -euo pipefail
bin=$1; scorer=$2; out=$3; iters=${4:-auto}
shift $(( $# >= 4 ? 4 : $# ))
[ "${1:-}" = "--" ] && shift
here=$(cd "$(dirname "$0")" && pwd)
. "$here/maps.sh"
py=${PYTHON:-/usr/bin/python3}
read -r -a transforms <<< "${TRANSFORMS:-none rot20 rot45 half double}"
suffix=$(variant_suffix "${ROOMSEG_VARIANT:-unfurnished}")
mkdir -p "$out"
printf '| map | transform | R | P | IoU | rooms | segments | seconds |\n|---|---|---|---|---|---|---|---|\n'
summary=()
for t in "${transforms[@]}"; do
  scores=()
  for m in "${names[@]}"; do
    dir=$out/$t/$m
    mkdir -p "$dir/input"
    if ! res=$("$py" "$here/transform_map.py" "$maps/$m$suffix.png" "$maps/${m}_gt_segmentation.png" "$t" "$dir/input" 2>&1); then
      echo "| $m | $t | transform failed: ${res//|/:} | | | | | |"; continue
    fi
    t0=$(date +%s.%N)
    if ! "$bin" "$dir/input/map.png" --resolution "$res" --out "$dir/run" --seed "${SEED:-1}" --iterations "$iters" \
         --quiet "$@" > "$dir/run.log" 2>&1; then
      echo "| $m | $t | run failed (see $dir/run.log) | | | | | |"; continue
    fi
    t1=$(date +%s.%N)
    if ! line=$("$scorer" "$dir/input/gt.png" "$dir/run/segmentation.png" 2>&1); then
      echo "| $m | $t | not scored: ${line//|/:} | | | | | |"; continue
    fi
    line="$line $(echo "$t1 - $t0" | bc)"
    echo "$line" | awk -v m="$m" -v t="$t" \
      '{printf "| %s | %s | %.1f | %.1f | %.1f | %s | %s | %.1f |\n", m, t, 100*$1, 100*$2, 100*$3, $4, $5, $6}'
    scores+=("$line")
  done
  if [ "${#scores[@]}" -gt 0 ]; then
    summary+=("$(printf '%s\n' "${scores[@]}" | awk -v t="$t" \
      '{r+=$1; p+=$2; i+=$3; s+=$6; n++} END {printf "| **average (%d maps)** | %s | **%.1f** | **%.1f** | **%.1f** | | | %.1f |", n, t, 100*r/n, 100*p/n, 100*i/n, s/n}')")
  fi
done
printf '%s\n' "${summary[@]}"
