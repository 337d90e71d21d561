#!/usr/bin/env bash
# Renders every built-in scene small on each backend and accel path into OUT_DIR, so that a
# structural change can be checked byte for byte: run it before and after, then
#   cmp -s each pair (the script does it with --compare BEFORE_DIR).
# Usage: scripts/image-identity.sh RTVK_BINARY OUT_DIR [--compare BEFORE_DIR]
# The hardware paths (rt-query, rt-pipeline) need a device with ray tracing: set VK_ICD_FILENAMES
# and friends to Mesa 25's lavapipe (scripts/private-mesa.sh) for them; without one they are
# skipped and said so.
set -uo pipefail
rtvk=$1 out=$2 before=${4:-}
mkdir -p "$out"
scenes="$("$rtvk" scene list | awk '$1 !~ /:N$/ {print $1}') spheres:300"
size=(--width 96 --spp 4 --depth 8 -q)
failed=0
for s in $scenes; do
  "$rtvk" render --scene "$s" "${size[@]}" --backend cpu -o "$out/$s.cpu.png" || failed=1
  for accel in bvh none rt-query rt-pipeline; do
    "$rtvk" render --scene "$s" "${size[@]}" --backend gpu --accel $accel --gpu-timeout 900 \
      -o "$out/$s.gpu-$accel.png" 2>"$out/$s.gpu-$accel.err" ||
      echo "skipped or failed: $s gpu $accel: $(head -c 200 "$out/$s.gpu-$accel.err")"
  done
done
if [[ -n $before ]]; then
  same=0 differ=0
  for f in "$before"/*.png; do
    n=$(basename "$f")
    if cmp -s "$f" "$out/$n"; then same=$((same + 1)); else differ=$((differ + 1)); echo "DIFFERS: $n"; fi
  done
  echo "$same byte-identical, $differ differ"
  [[ $differ == 0 ]] || failed=1
fi
exit $failed
