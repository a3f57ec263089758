#!/usr/bin/env bash
# ROS end-to-end test: roscore on loopback on a free port, a ksmc node started by roslaunch
# from its launch file (package folder build/ros/ksmc), and a check program that publishes
# the input and checks the node's outputs. Exit 77 (CTest: skipped) without roscore /
# roslaunch.
#   run_node_test.sh ROS_PACKAGE_DIR WORK_DIR LAUNCH_FILE "ARG:=VALUE ..." CHECK [CHECK_ARGS...]
# The launch file gets output_root:=WORK_DIR/out besides the given arguments.
set -euo pipefail
PKG_DIR=$1 WORK=$2 LAUNCH=$3 LAUNCH_ARGS=$4
shift 4
for tool in roscore roslaunch; do
  command -v $tool >/dev/null || { echo "SKIP: $tool not installed (Debian package ros-core; scripts/install-deps.sh)"; exit 77; }
done
rm -rf "$WORK" && mkdir -p "$WORK/out"
PORT=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI=http://127.0.0.1:$PORT ROS_IP=127.0.0.1 ROS_HOME=$WORK/ros_home ROS_LOG_DIR=$WORK/ros_log
export ROS_PACKAGE_PATH=$PKG_DIR
pids=()
stop_all() {  # SIGINT: roslaunch stops its nodes, roscore its master; newest first
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do kill -INT "${pids[i]}" 2>/dev/null || true; wait "${pids[i]}" 2>/dev/null || true; done
  pids=()
}
trap stop_all EXIT
roscore -p "$PORT" >"$WORK/roscore.log" 2>&1 &
pids+=($!)
up=0
for _ in $(seq 1 100); do
  if python3 -c "import xmlrpc.client; xmlrpc.client.ServerProxy('$ROS_MASTER_URI').getPid('/t')" 2>/dev/null; then up=1; break; fi
  sleep 0.3
done
[ $up = 1 ] || { echo "FAIL: roscore did not come up on $ROS_MASTER_URI"; cat "$WORK/roscore.log"; exit 1; }
echo "roscore up on $ROS_MASTER_URI"
# shellcheck disable=SC2086  # LAUNCH_ARGS is a list of name:=value words
roslaunch ksmc "$LAUNCH" $LAUNCH_ARGS output_root:="$WORK/out" >"$WORK/launch.log" 2>&1 &
pids+=($!)
status=0
"$@" || status=$?
stop_all
echo "--- node output (roslaunch ksmc $LAUNCH)"
grep -E "ksmc" "$WORK/launch.log" || cat "$WORK/launch.log"
exit $status
