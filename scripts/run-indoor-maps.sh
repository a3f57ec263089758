#!/usr/bin/env bash
# Runs the indoor binary on every map of the Bormann/IPA test set (the 20 benchmark maps and
# the real SLAM maps; ground truth, furnished and trash-bin variants skipped) and on the
# ubremen-cartesium YAML, and prints one table row per map (exit code, K(W,M), units, seconds).
# Exits non-zero if any run fails.
#   scripts/run-indoor-maps.sh [BINARY] [ITERATIONS] [OUT_ROOT] [MAP...]
# Defaults: build/bin/indoor (or build/bin/indoor-dev), 10000, /tmp/ksmc-indoor-maps, all maps.
set -u
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${1:-}"
if [ -z "$bin" ]; then
  for b in "$here/build/bin/indoor" "$here/build/bin/indoor-dev"; do [ -x "$b" ] && bin="$b" && break; done
fi
[ -n "$bin" ] && [ -x "$bin" ] || { echo "run-indoor-maps: no indoor binary (give one as first argument)" >&2; exit 2; }
iters="${2:-10000}"
root="${3:-/tmp/ksmc-indoor-maps}"
shift $(( $# > 3 ? 3 : $# ))
shared="${KSMC_SHARED_DIR:-$here/../shared}"
maps=("$@")
if [ ${#maps[@]} -eq 0 ]; then
  while IFS= read -r f; do maps+=("$f"); done < <(find "$shared/data/maps/bormann_ipa/test_maps" -maxdepth 1 \
      \( -name '*.png' -o -name '*.pgm' \) ! -name '*_gt_*' ! -name '*furnitures*' ! -name '*trashbins*' | sort)
  maps+=("$shared/data/maps/rose2_ros/carmen/ubremen-cartesium.yaml")
fi
failed=0
printf '| map | exit | K(W,M) | units | doors | seconds |\n|---|---|---|---|---|---|\n'
for m in "${maps[@]}"; do
  name="$(basename "$m")"
  out="$root/${name%.*}"
  rm -rf "$out"
  args=("$m" --out "$out" --seed 1 --iterations "$iters" --quiet)
  case "$m" in *.yaml) ;; *) args+=(--resolution 0.05) ;; esac
  "$bin" "${args[@]}" 2> "$root.$name.err" >/dev/null
  rc=$?
  if [ $rc -eq 0 ] && [ -f "$out/world.json" ]; then
    row=$(python3 -c "import json,sys; m=json.load(open(sys.argv[1]))['metrics']; print('%.4f | %d | %d | %.1f' % (m['cell_prediction_rate'], m['units'], m['doors'], m['seconds']))" "$out/world.json" 2>/dev/null || echo "? | ? | ? | ?")
  else
    row="- | - | - | -"; failed=1
    sed 's/^/    /' "$root.$name.err" >&2
  fi
  rm -f "$root.$name.err"
  printf '| %s | %d | %s |\n' "$name" "$rc" "$row"
done
exit $failed
