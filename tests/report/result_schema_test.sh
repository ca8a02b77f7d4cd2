#!/usr/bin/env bash
# Runs cloudshape-recognize over synthetic clouds (every shape, whole and seen from one side, a
# noisy one, a plane) and real files (one holding two objects), and validates every line.
set -euo pipefail
recognize="$1" synth="$2" schema="$3" real="$4"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

"$synth" suite --out "$work/whole" --points 4000 --count 1 --seed 3 >/dev/null
"$synth" suite --out "$work/view" --points 4000 --count 1 --seed 4 --partial --format ply >/dev/null
"$synth" shape --shape box --dims 3,2,1 --points 4000 --noise 0.01 --outliers 0.03 --seed 5 \
  -o "$work/noisy_box.xyz" >/dev/null
# A plane: an unknown object with its reason and no dimensions.
awk 'BEGIN { for (i = 0; i < 20; i++) for (j = 0; j < 20; j++) print 0.1 * i, 0.1 * j, 0.05 * i - 0.1 * j }' \
  >"$work/coplanar.xyz"
files=("$work"/whole/*.pcd "$work"/view/*.ply "$work/noisy_box.xyz" "$work/coplanar.xyz")
# Real captures as users give them: the data is required, not skipped.
for f in pcl/milk.pcd pcl/mOSD_learn0_boxes.pcd spherecalib/example3_L1_S1_lidar_sphere.xyz \
         ycb/056_tennis_ball_google16k_nontextured.ply; do
  [[ -f "$real/$f" ]] || { echo "missing real file $real/$f" >&2; exit 1; }
  files+=("$real/$f")
done
"$recognize" "${files[@]}" >"$work/out.jsonl"
lines=$(wc -l <"$work/out.jsonl")
if [[ "$lines" -ne "${#files[@]}" ]]; then
  echo "expected ${#files[@]} result lines, got $lines" >&2
  exit 1
fi
python3 "$here/validate_results.py" "$schema" "$work/out.jsonl"
