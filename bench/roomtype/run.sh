#!/usr/bin/env bash
# bench/roomtype/run.sh INDOOR_BIN OUT_DIR [ITERATIONS] [SEEDS] [-- extra indoor flags]
# Unit types on real maps: runs the indoor binary on the five maps of the Bormann et al.
# set that have a hallway or room label map in training_maps/ (Freiburg52_scan, lab_a, lab_d,
# lab_intel, lab_ipa; lab_a and lab_d are not among the 20 segmentation maps) and scores the
# types of segmentation.png's units cell by cell (score.py: Corr = hallway; Room, Hall,
# Other = room). Prints per-map rows (median over SEEDS) and the mean over the maps; Corr P
# is "nan" where no seed's run has a Corr unit, and its mean is over the other maps.
# Environment: KSMC_SHARED_DIR (where ../shared is).
set -euo pipefail
bin=$1; out=$2; iters=${3:-10000}; seeds=${4:-"1 2 3"}
shift $(( $# >= 4 ? 4 : $# ))
[ "${1:-}" = "--" ] && shift
here=$(cd "$(dirname "$0")" && pwd)
root=${KSMC_SHARED_DIR:-$here/../../../shared}/data/maps/bormann_ipa
if [ ! -d "$root/training_maps" ]; then
  echo "bench/roomtype: $root/training_maps is absent; skipped"
  exit 0
fi
py=${PYTHON:-/usr/bin/python3}
# map, label file, what its grey cells are
maps=("Freiburg52_scan Freiburg52_scan_hallway_training.png hallway"
      "lab_a lab_a_hallway_training_map.png hallway"
      "lab_d lab_d_room_training_map.png room"
      "lab_intel lab_intel_hallway_training_map.png hallway"
      "lab_ipa lab_ipa_hallway_training_map.png hallway")
mkdir -p "$out"
printf '| map | hallway cells | room cells | Corr P | Corr R | Corr F1 | room acc | accuracy | no unit | units (Corr) |\n'
printf '|---|---|---|---|---|---|---|---|---|---|\n'
all=()
for entry in "${maps[@]}"; do
  read -r m labels kind <<< "$entry"
  rows=()
  for s in $seeds; do
    dir=$out/$m/seed$s
    mkdir -p "$out/$m"
    if ! "$bin" "$root/test_maps/$m.png" --resolution 0.05 --out "$dir" --seed "$s" --iterations "$iters" \
         --quiet "$@" > "$dir.log" 2>&1; then
      echo "| $m | run failed ($dir.log) | | | | | | | | |"; continue
    fi
    line=$("$py" "$here/score.py" "$root/training_maps/$labels" "$kind" "$dir/segmentation.png" "$dir/world.json")
    units=$("$py" -c 'import json,sys; u=json.load(open(sys.argv[1]))["units"]; print(len(u), sum(x.get("type")=="Corr" for x in u))' "$dir/world.json")
    rows+=("$line $units")
  done
  [ "${#rows[@]}" -gt 0 ] || continue
  # Medians over the seeds; Corr P is undefined (nan) in a run with no Corr unit and is then
  # left out of its median.
  med=$(printf '%s\n' "${rows[@]}" | "$py" -c '
import math, sys, statistics as st
r = [l.split() for l in sys.stdin if l.strip()]
def c(i):
    v = [float(x[i]) for x in r if not math.isnan(float(x[i]))]
    return st.median(v) if v else float("nan")
print(f"{int(c(0))} {int(c(1))} {c(2):.3f} {c(3):.3f} {c(4):.3f} {c(5):.3f} {c(6):.3f} {c(7):.3f} {c(8):g} {c(9):g}")')
  read -r h rm p r f ra a u n nc <<< "$med"
  echo "| $m | $h | $rm | $p | $r | $f | $ra | $a | $u | $n ($nc) |"
  all+=("$med")
done
if [ "${#all[@]}" -gt 0 ]; then
  printf '%s\n' "${all[@]}" | awk '{if ($3 != "nan") {p+=$3; np++}; r+=$4; f+=$5; ra+=$6; a+=$7; u+=$8; n++}
    END {printf "| **mean (%d maps)** | | | **%.3f** (%d maps) | **%.3f** | **%.3f** | **%.3f** | **%.3f** | %.3f | |\n", n, np ? p/np : 0, np, r/n, f/n, ra/n, a/n, u/n}'
fi
