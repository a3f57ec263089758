#!/usr/bin/env bash
# bench/indoor_ablation/run.sh BUILD_DIR OUT_DIR [ITERATIONS] [SEEDS]
# The ablation of issue 11 (seed Fig. 3.34 / 3.35): the variants of domains/indoor.ksm built
# by `cmake --build BUILD_DIR --target indoor_ablation` (weak prior only, + the seed's
# same-length prior, + no slivers, + not on walls, + one space, + no hollow units, + only two
# rooms share a wall length) and the shipped binary (full knowledge: + a corridor continues), on lab_b.png and five
# Bormann maps. VARIANTS="a b ..." runs a subset. Per variant and map
# (median over SEEDS): K, units, R / P / IoU against the Bormann ground truth
# (segmentation.png, else labels.png), the conditional prior bindings (SaLe pairs) more than
# 2 sd off, and the spread (sd) of the unit count and of the log posterior over the last
# 1,000 iterations (samples.jsonl, thin 1).
set -euo pipefail
build=$1; out=$2; iters=${3:-20000}; seeds=${4:-"1 2 3"}
here=$(cd "$(dirname "$0")" && pwd)
maps=${KSMC_SHARED_DIR:-$here/../../../shared}/data/maps/bormann_ipa/test_maps
if [ ! -d "$maps" ]; then
  echo "bench/indoor_ablation: $maps is absent; skipped"
  exit 0
fi
scorer=$build/bin/roomseg_score
names=(lab_b office_a office_c lab_a_scan lab_d_scan Freiburg52_scan)
variants=(${VARIANTS:-weak seed no_sliver not_wall one_space no_hollow sale full})
mkdir -p "$out"
printf '| variant | map | K | units | R | P | IoU | SaLe > 2 sd | sd units (last 1000) | sd log p (last 1000) | it/s |\n'
printf '|---|---|---|---|---|---|---|---|---|---|---|\n'
for v in "${variants[@]}"; do
  bin=$build/bin/indoor_ablation_$v; [ "$v" = full ] && bin=$build/bin/indoor
  [ -x "$bin" ] || { echo "| $v | missing: cmake --build $build --target indoor_ablation | | | | | | | | | |"; continue; }
  for m in "${names[@]}"; do
    rows=()
    for s in $seeds; do
      dir=$out/$v/$m/seed$s
      mkdir -p "$out/$v/$m"
      args=(--resolution 0.05 --thresholds bormann)
      [ "$m" = lab_b ] && args=()
      "$bin" "$maps/$m.png" "${args[@]}" --out "$dir" --seed "$s" --iterations "$iters" --quiet \
        --samples 1000 --thin 1 --burn-in $((iters - 1000)) > "$dir.log" 2>&1 || { echo "| $v | $m | run failed ($dir.log) |"; continue; }
      score="nan nan nan"
      gt=$maps/${m}_gt_segmentation.png
      if [ -f "$gt" ]; then
        seg=$dir/segmentation.png; [ -f "$seg" ] || seg=$dir/labels.png
        score=$("$scorer" "$gt" "$seg" | awk '{print $1, $2, $3}')
      fi
      rows+=("$(python3 - "$dir" "$score" <<'PY'
import json, statistics, sys
d, score = sys.argv[1], sys.argv[2].split()
m = json.load(open(d + '/world.json'))['metrics']
units, lp = [], []
for line in open(d + '/samples.jsonl'):
    s = json.loads(line)
    units.append(len(s['state']['units'])); lp.append(s['log_posterior'])
sd = lambda x: statistics.pstdev(x) if len(x) > 1 else 0.0
print(m['cell_prediction_rate'], m['units'], *score, m.get('conditional_beyond_2sd', 0), sd(units), sd(lp), m['iterations_per_second'])
PY
)")
    done
    [ "${#rows[@]}" -gt 0 ] || continue
    printf '%s\n' "${rows[@]}" | python3 -c "
import sys, statistics
rows = [list(map(float, l.split())) for l in sys.stdin if l.strip()]
med = [statistics.median(c) for c in zip(*rows)]
f = lambda x, k: 'n/a' if x != x else k.format(x)
print('| $v | $m | {} | {:.0f} | {} | {} | {} | {:.0f} | {:.2f} | {:.1f} | {:.0f} |'.format(
  f(med[0], '{:.4f}'), med[1], f(100*med[2], '{:.1f}'), f(100*med[3], '{:.1f}'), f(100*med[4], '{:.1f}'), med[5], med[6], med[7], med[8]))"
  done
done
