#!/usr/bin/env bash
# ISM render time of two tofsim binaries, alternating, N runs each: the
# process wall (s) and the render's own stats.seconds, on the late_light.py
# protocol (64 x 64, RSM 32^2, ISMs 32^2) with the config's points per VPL
# (configs/cornell_box.yaml: 2000) and with the key's default.
#   bash bench/ism_bias/ab_time.sh OLD_TOFSIM NEW_TOFSIM [N=5]
set -euo pipefail
cd "$(dirname "$0")/../.."
old="$1" new="$2" n="${3:-5}"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
sets=(--set output.video=false --set 'sensors=[]' --set 'output.components=[]'
      --set 'light.cone_angle=30 deg' --set 'light.cone_falloff=0 deg' --set 'time.start=1.5 m'
      --set 'time.bin_width=20 ps' --set time.bins=371 --set 'camera.resolution=[64, 64]'
      --set render.indirect.visibility=ism)
# Each binary with the config's 2000 points, then with its own default
# (main: 1000; since the slope bias: 0, two per texel, 2048 at ISM 32^2).
for case in "2000 2000" "1000 0"; do
  read -r old_points new_points <<<"$case"
  for i in $(seq "$n"); do
    for which in old new; do
      bin=${!which}
      points_var=${which}_points
      start=$(date +%s.%N)
      "$bin" render configs/cornell_box.yaml --backend cpu -q -o "$out/$which" "${sets[@]}" \
        --set "render.indirect.points_per_vpl=${!points_var}"
      end=$(date +%s.%N)
      render=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['stats']['seconds'])" "$out/$which/transient.json")
      printf '%s points_per_vpl=%s run %d: process %.3f s, render %.3f s\n' "$which" "${!points_var}" "$i" \
        "$(echo "$end - $start" | bc)" "$render"
    done
  done
done
