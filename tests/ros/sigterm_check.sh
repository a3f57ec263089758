#!/usr/bin/env bash
# CHECK for run_node_test.sh (issue 16): SIGTERM, what roslaunch and Slurm send, reaches the
# indoor node while it runs on a map. The run must stop, write the complete outputs of its
# best state marked "interrupted": "SIGTERM", and the node must shut down promptly (before
# roslaunch would escalate to SIGKILL) instead of waiting for the next map.
#   sigterm_check.sh WORK       (WORK: run_node_test.sh's folder; launch.log, out/ are there)
set -uo pipefail
WORK=$1
log="$WORK/launch.log"
# The node writes each map it receives into a fresh temporary folder (ros/src/domain_run.cpp)
# and runs on it; its INFO lines are block-buffered in launch.log, so the folder is the sign.
node=""
for _ in $(seq 1 1200); do
  node=$(pgrep -f "ksmc_indoor_node.*$WORK" | head -1)
  [ -n "$node" ] && [ -f "${TMPDIR:-/tmp}/ksmc-indoor-node-$node-1/map.yaml" ] && break
  sleep 0.1
done
[ -n "$node" ] || { echo "FAIL: no ksmc_indoor_node process for $WORK"; cat "$log"; exit 1; }
[ -f "${TMPDIR:-/tmp}/ksmc-indoor-node-$node-1/map.yaml" ] || { echo "FAIL: the node never started a run"; cat "$log"; exit 1; }
sleep 2
start=$(date +%s.%N)
kill -TERM "$node"
for _ in $(seq 1 300); do kill -0 "$node" 2>/dev/null || break; sleep 0.1; done
took=$(echo "$(date +%s.%N) - $start" | bc)
if kill -0 "$node" 2>/dev/null; then
  echo "FAIL: the node still runs 30 s after SIGTERM"; kill -KILL "$node"; exit 1
fi
summary="$WORK/out/map_1/summary.json"
[ -f "$summary" ] || { echo "FAIL: no $summary after SIGTERM"; ls -la "$WORK/out"; exit 1; }
grep -q '"interrupted": "SIGTERM"' "$summary" || { echo "FAIL: $summary lacks \"interrupted\": \"SIGTERM\""; exit 1; }
grep -q "run interrupted (exit 143)" "$log" || { echo "FAIL: the node did not report the interruption"; exit 1; }
for f in world.json segmentation.png; do
  [ -f "$WORK/out/map_1/$f" ] || { echo "FAIL: $f missing in the interrupted run's folder"; exit 1; }
done
printf 'ok   SIGTERM during a run: node stopped %.1f s after the signal; %s marked "interrupted": "SIGTERM"\n' "$took" "$summary"
