#!/usr/bin/env bash
# The bad-input suite (issue 16): every case a careless user or a batch system produces.
# Each case states its expected exit code and a fragment of the message, and what must be
# true of the output folder afterwards: nothing left behind ("none DIR"), the previous
# complete folder untouched ("intact DIR"), or a complete new one ("complete DIR").
#   tests/badinput/run.sh BIN_DIR SOURCE_DIR        (CTest: badinput)
# BIN_DIR holds ksmc, ksmc_toy_domain and, when their kits are built, indoor and tabletop.
set -uo pipefail
BIN="$(cd "$1" && pwd)"
SRC="$(cd "$2" && pwd)"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/ksmc-badinput-XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"
. "$SRC/tests/badinput/cases.sh" || exit 1
. "$SRC/tests/badinput/cases_fault.sh" || exit 1

cases=0
failed=0
skipped=0

# Digest of a folder (names, sizes, contents), to compare before and after.
digest() { [ -d "$1" ] && (cd "$1" && find . -type f -print0 | sort -z | xargs -0 sha256sum) | sha256sum || echo absent; }

# expect NAME CODE FRAGMENT CHECK DIR -- COMMAND...
expect() {
  local name="$1" code="$2" fragment="$3" check="$4" dir="$5"
  shift 6
  cases=$((cases + 1))
  local before
  before="$(digest "$dir")"
  local start end out rc
  start=$(date +%s.%N)
  out="$(timeout -k 5 120 "$@" 2>&1 >/dev/null)"
  rc=$?
  end=$(date +%s.%N)
  local ok=1 why=""
  [ "$rc" -eq "$code" ] || { ok=0; why="exit $rc, expected $code"; }
  # A fragment starting with ^ must start the message's first line.
  if [[ "$fragment" == ^* ]]; then
    [[ "$out" == "${fragment#^}"* ]] || { ok=0; why="$why; message does not start with '${fragment#^}'"; }
  elif [ -n "$fragment" ] && [[ "$out" != *"$fragment"* ]]; then ok=0; why="$why; message lacks '$fragment'"; fi
  case "$check" in
    none) [ ! -e "$dir" ] || { ok=0; why="$why; $dir was created"; } ;;
    intact) [ "$(digest "$dir")" = "$before" ] || { ok=0; why="$why; $dir changed"; } ;;
    complete) [ -f "$dir/summary.json" ] || { ok=0; why="$why; $dir/summary.json missing"; } ;;
    -) ;;
  esac
  # No staging folder or temporary file may stay beside the output.
  # (Except after SIGKILL, which leaves its hidden staging folder for the next run to remove.)
  if [ "$dir" != "-" ] && [ "$code" -ne 137 ] \
     && grep -qE "^\.$(basename "$dir")\.(staging|old)-|\.tmp\." <<< "$(ls -a "$(dirname "$dir")")"; then
    ok=0
    why="$why; a staging folder or temporary file is left"
  fi
  local first_line="${out%%$'\n'*}"
  printf '%-4s %-48s exit %3d  %6.2f s  %s\n' "$([ $ok -eq 1 ] && echo ok || echo FAIL)" "$name" "$rc" \
    "$(echo "$end - $start" | bc)" "${first_line:0:150}"
  if [ $ok -eq 0 ]; then
    failed=$((failed + 1))
    echo "     -> $why"
    echo "$out" | head -5 | sed 's/^/     | /'
  fi
}

skip() {
  skipped=$((skipped + 1))
  printf 'skip %-48s %s\n' "$1" "$2"
}

run_cases "$BIN" "$SRC"
run_fault_cases "$BIN"
echo "badinput: $cases cases, $failed failed, $skipped skipped"
[ $failed -eq 0 ] && [ $cases -gt 0 ]
