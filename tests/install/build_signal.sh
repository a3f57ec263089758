#!/usr/bin/env bash
# ksmc build under a real signal (issue 16): the installed ksmc builds the segments example;
# while it compiles, the whole process group gets SIGTERM (what Slurm and roslaunch send);
# a second run gets SIGINT twice while CMake configures (Ctrl-C pressed again, or `timeout`).
# Each must exit 128 + signal with "interrupted by SIG...", remove its temporary work folder,
# write no binary, and leave no CMake or compiler process behind.
#   tests/install/build_signal.sh PREFIX SOURCE_DIR
set -uo pipefail
PREFIX="$1"
SRC="$2"
KSMC="$PREFIX/bin/ksmc"
DOMAIN="$SRC/examples/segments/segments.ksm"
[ -f "$DOMAIN" ] || DOMAIN="$SRC/domains/tabletop.ksm"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/ksmc-build-signal-XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
failed=0

# run_and_signal NAME SIGNAL COUNT EXPECTED_EXIT PHASE
# PHASE: the file of the work folder whose appearance means the step to interrupt runs:
# build (CMake configuring) or build/Makefile (configured: compiling).
run_and_signal() {
  local name="$1" sig="$2" count="$3" code="$4" phase="$5"
  local tmp="$WORK/$name/tmp" out="$WORK/$name/bin/domain" log="$WORK/$name/log"
  mkdir -p "$tmp" "$WORK/$name/bin"
  # setsid: the build and its children form their own process group, as under a job runner.
  TMPDIR="$tmp" setsid "$KSMC" build "$DOMAIN" -o "$out" -j 2 > "$log" 2>&1 &
  local pid=$!
  # Wait (up to 120 s) until the step runs.
  local waited=0
  while [ $waited -lt 1200 ] && ! compgen -G "$tmp/ksmc-build-*/$phase" > /dev/null; do
    sleep 0.1
    waited=$((waited + 1))
  done
  if ! compgen -G "$tmp/ksmc-build-*/$phase" > /dev/null; then
    echo "FAIL $name: $phase never appeared"; sed 's/^/     | /' "$log" | tail -8; failed=$((failed + 1))
    kill -KILL -- "-$pid" 2>/dev/null; wait "$pid" 2>/dev/null; return
  fi
  sleep 1
  local start=$(date +%s.%N)
  for _ in $(seq "$count"); do kill "-$sig" -- "-$pid" 2>/dev/null; sleep 0.2; done
  wait "$pid"
  local rc=$?
  local took
  took=$(echo "$(date +%s.%N) - $start" | bc)
  local why=""
  [ "$rc" -eq "$code" ] || why="$why exit $rc, expected $code;"
  grep -q "interrupted by SIG$sig" "$log" || why="$why no 'interrupted by SIG$sig' in the output;"
  [ -z "$(ls -A "$tmp")" ] || why="$why work folder left: $(ls -A "$tmp");"
  [ ! -e "$out" ] || why="$why a binary was written;"
  [ -z "$(ls -A "$WORK/$name/bin")" ] || why="$why files next to the binary: $(ls -A "$WORK/$name/bin");"
  if pgrep -f "$tmp/ksmc-build-" > /dev/null; then why="$why processes left: $(pgrep -af "$tmp/ksmc-build-" | head -3);"; fi
  if [ -z "$why" ]; then
    printf 'ok   %-34s exit %d in %.1f s after the signal: %s\n' "$name" "$rc" "$took" "$(grep 'interrupted' "$log" | head -1)"
  else
    echo "FAIL $name:$why"; sed 's/^/     | /' "$log" | tail -8; failed=$((failed + 1))
  fi
}

run_and_signal "SIGTERM while compiling" TERM 1 143 build/Makefile
run_and_signal "SIGINT twice while configuring" INT 2 130 build
echo "build_signal: $failed failed"
[ $failed -eq 0 ]
