# Shared by tools/bench_mcap.sh and tools/bench_replay.sh (source it after lib/pipeline_run.sh,
# don't run it): the recording both measure, N frames of a 640 x 480 depth camera at a rate.
# shellcheck shell=bash
# shellcheck disable=SC2154  # bin and work: set by lib/pipeline_run.sh

# cs_replay_recording OUT FRAMES RATE COMPRESSION: three cloudshape-synth scenes (a table with
# three objects, 640 x 480 camera, seeds 1 2 3) in $work, written in turn as FRAMES PointCloud2
# messages (float32 x y z rgb, organized) 1/RATE s apart, chunks none, lz4 or zstd.
cs_replay_recording() {
  local out="$1" frames="$2" rate="$3" compression="$4" seed
  for seed in 1 2 3; do
    [[ -s "$work/frame$seed.pcd" ]] ||
      "$bin/cloudshape-synth" scene --layout row --count 3 --seed "$seed" -o "$work/frame$seed.pcd" >/dev/null
  done
  "$bin/cloudshape-mcap-bench" write "$work"/frame{1,2,3}.pcd --frames "$frames" --rate "$rate" \
    --compression "$compression" -o "$out"
}

# cs_percentiles: the numbers on stdin (one a line) as "p50 p90 p99 max" (nearest rank), or
# "nan nan nan nan" when there are none.
cs_percentiles() {
  sort -g | awk '{v[NR] = $1}
    function rank(p,  r) {r = int(p * NR + 0.999999); if (r < 1) r = 1; return v[r]}
    END {if (NR == 0) {print "nan nan nan nan"; exit}
         printf "%.1f %.1f %.1f %.1f\n", rank(0.5), rank(0.9), rank(0.99), v[NR]}'
}
