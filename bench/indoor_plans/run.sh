#!/usr/bin/env bash
# bench/indoor_plans/run.sh INDOOR_BIN MAKE_PLANS_BIN SCORE_BIN OUT [COUNT] [ITERS]
# Generates COUNT synthetic plans (ksmc-make-plans, seed $SEED, default 1), runs the indoor
# binary on each (--seed $RUN_SEED, default 1), scores world.json against the plan's truth with indoor_plan_score
# and prints a markdown row per plan and the mean row. Fails when any step fails.
set -euo pipefail
bin=$1; make_plans=$2; scorer=$3; out=$4; count=${5:-12}; iters=${6:-10000}
mkdir -p "$out"
"$make_plans" --count "$count" --seed "${SEED:-1}" --out "$out/plans" > "$out/plans.log"
printf '| plan | unit P | unit R | type acc | door P | door R | door F1 | adj F1 | door-graph F1 | topology F1 | units true | units found | seconds |\n'
printf '|---|---|---|---|---|---|---|---|---|---|---|---|---|\n'
rows=()
for (( k = 0; k < count; k++ )); do
  dir=$out/$k
  t0=$(date +%s.%N)
  if ! "$bin" "$out/plans/plan_$k.yaml" --out "$dir" --seed "${RUN_SEED:-1}" --iterations "$iters" --quiet > "$dir.log" 2>&1; then
    echo "indoor failed on plan_$k (see $dir.log)" >&2
    exit 1
  fi
  t1=$(date +%s.%N)
  line=$("$scorer" "$out/plans/plan_${k}_truth.json" "$dir/world.json")
  echo "$line $t0 $t1" | awk -v k="$k" \
    '{printf "| %d | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %d | %d | %.1f |\n", k, $1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $14-$13}'
  rows+=("$line")
done
printf '%s\n' "${rows[@]}" | awk \
  '{for (i = 1; i <= 11; i++) s[i] += $i; n++}
   END {printf "| **mean (%d plans)** | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.1f | %.1f | |\n",
        n, s[1]/n, s[2]/n, s[3]/n, s[4]/n, s[5]/n, s[6]/n, s[7]/n, s[8]/n, s[9]/n, s[10]/n, s[11]/n}'
