#!/usr/bin/env bash
# bench/indoor/plateau_maps.sh BENCH_INDOOR_RUN [LONG] [SEED_RUNS]
# Wall time to plateau per map (issue 11, "Performance"): bench_indoor_run's plateau criterion
# (best(i + 5000) - best(i) <= min_gain, strict and one cell) on each of the 20 Bormann et al.
# maps (unfurnished, ../shared/data/maps/bormann_ipa/test_maps) and on lab_b.png, SEED_RUNS runs
# each (seeds 1..SEED_RUNS, default 1) of at most LONG iterations (default 200000), one thread.
# Prints one row per map and run. Environment: PLATEAU_MAPS ("m1 m2 ...": a subset),
# KSMC_SHARED_DIR (where ../shared is).
set -euo pipefail
bin=$1; long=${2:-200000}; runs=${3:-1}
here=$(cd "$(dirname "$0")" && pwd)
maps=${KSMC_SHARED_DIR:-$here/../../../shared}/data/maps/bormann_ipa/test_maps
if [ ! -d "$maps" ]; then
  echo "bench/indoor/plateau_maps.sh: $maps is absent; skipped"
  exit 0
fi
names=(lab_b Freiburg101_scan Freiburg52_scan Freiburg79_scan NLB lab_a_scan lab_b_scan lab_c_scan lab_d_scan
       lab_f_scan lab_intel lab_ipa office_a office_b office_c office_d office_e office_f office_g
       office_h office_i)
[ -n "${PLATEAU_MAPS:-}" ] && read -r -a names <<< "$PLATEAU_MAPS"
printf '| map | run | iterations run | seconds | K(W,M) | one cell: i | s at i | strict: i | s at i |\n'
printf '|---|---|---|---|---|---|---|---|---|\n'
for m in "${names[@]}"; do
  img=$maps/$m.png
  [ -f "$img" ] || { echo "| $m | missing input | | | | | | | |"; continue; }
  "$bin" 0 --long "$long" --runs "$runs" --map "$img" | awk -F'|' -v m="$m" '
    /^\| [0-9]+ \|/ { gsub(/ /, "", $0); split($0, f, "|");
      printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", m, f[2], f[3], f[4], f[6], f[7], f[8], f[10], f[11] }'
done
