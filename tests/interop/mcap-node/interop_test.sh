#!/usr/bin/env bash
# MCAP against the libraries behind Foxglove (issue 12, item 4), in the default tests:
#  1. @mcap/core + @foxglove/rosmsg2-serialization write PointCloud2 recordings (lz4 and zstd
#     chunks, float32 and float64, organized or not); cloudshape-recognize reads each message and
#     finds exactly what it finds in a PCD file of the same points.
#  2. cloudshape-recognize --record writes a recording; @mcap/core reads and validates it and
#     every message decodes from the file's own schema text, its values matching the JSON.
#   interop_test.sh BIN_DIR      (the npm packages: tools/test.sh runs npm ci here)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
bin="${1:?usage: interop_test.sh BIN_DIR}"
[[ -d "$here/node_modules/@mcap/core" ]] || {
  echo "interop_test.sh: npm packages missing in $here: tools/test.sh installs them (npm ci)" >&2
  exit 1
}
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

shapes=("box 30,20,10" "cylinder 8,25" "sphere 12")
clouds=()
for s in "${shapes[@]}"; do
  read -r shape dims <<<"$s"
  "$bin/cloudshape-synth" shape --shape "$shape" --dims "$dims" --points 8000 --seed 5 -o "$work/$shape.xyz" >/dev/null
  clouds+=("$work/$shape.xyz")
done

echo "1. recordings written by @mcap/core, read by cloudshape-recognize"
node "$here/write_clouds.js" "$work/node" "${clouds[@]}"
for variant in lz4_float32 zstd_float64_organized zstd_float32_organized lz4_float64; do
  "$bin/cloudshape-recognize" "$work/node/$variant.mcap" >"$work/$variant.mcap.jsonl"
  pcds=()
  for k in "${!clouds[@]}"; do pcds+=("$work/node/${variant}_$k.pcd"); done
  "$bin/cloudshape-recognize" "${pcds[@]}" >"$work/$variant.pcd.jsonl"
  echo -n "   $variant: "
  node "$here/compare_results.js" "$work/$variant.pcd.jsonl" "$work/$variant.mcap.jsonl"
done

echo "2. recordings written by cloudshape, validated and decoded by @mcap/core and rosmsg2-serialization"
"$bin/cloudshape-recognize" --record "$work/replayed.mcap" --record-clouds "$work/node/zstd_float32_organized.mcap" \
  >"$work/replayed.jsonl"
echo -n "   recognize --record --record-clouds of a recording: "
node "$here/check_recording.js" "$work/replayed.mcap" "$work/replayed.jsonl" --clouds --stamps 100,101,102
"$bin/cloudshape-recognize" --record "$work/files.mcap" "$work/node/lz4_float64_0.pcd" "${clouds[@]}" >"$work/files.jsonl"
echo -n "   recognize --record of files: "
node "$here/check_recording.js" "$work/files.mcap" "$work/files.jsonl"
# A 640 x 480 scene (several partial objects, organized) and a flat patch (an unknown object).
"$bin/cloudshape-synth" scene --layout row --count 3 --seed 2 -o "$work/scene.pcd" >/dev/null
awk 'BEGIN {for (i = 0; i < 60; ++i) for (j = 0; j < 60; ++j) printf "%g %g 1\n", i * 0.1, j * 0.1}' >"$work/flat.xyz"
"$bin/cloudshape-recognize" --record "$work/scene.mcap" --record-clouds "$work/scene.pcd" "$work/flat.xyz" \
  >"$work/scene.jsonl"
grep -q '"shape":"unknown"' "$work/scene.jsonl" || { echo "interop_test.sh: the flat patch was not unknown" >&2; exit 1; }
echo -n "   recognize --record --record-clouds of a scene and an unknown object: "
node "$here/check_recording.js" "$work/scene.mcap" "$work/scene.jsonl" --clouds
