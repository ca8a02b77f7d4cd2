#!/usr/bin/env bash
# What a ROS 2 PointCloud2 adds over a raw cloud of the same points, end to end, through the five
# services on one host (docs/ros2.md "Latency"). Prints one Markdown table row per point_step.
#
#   tools/bench_ros2.sh [--frames N] [--steps "16 32"] [--domain N] [--max-added MS] [FILE.pcd]
#
# FILE: a 640 x 480 depth-camera frame (default: a real Kinect frame of ../shared/data, else a
# synthetic 640 x 480 scene). For each point_step the file's points go alternately as
# cloudshape_raw_cloud and as sensor_msgs/PointCloud2 (float32 x y z + rgb, ROS 2 sensor-data
# QoS), one at a time (cloudshape-bench-ros2); "sent again": clouds that got no result in 10 s
# (a best-effort frame that lost a fragment). --max-added MS: exit 1 when the median added
# overhead of a point_step exceeds MS. Needs a build (build/bin).
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=bench_ros2.sh
# shellcheck source-path=SCRIPTDIR source=lib/deps.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

frames=15
steps="16 32"
domain=$((80 + RANDOM % 20))
max_added=""
file=""
while (($#)); do
  case "$1" in
    --frames) frames="$2"; shift ;;
    --steps) steps="$2"; shift ;;
    --domain) domain="$2"; shift ;;
    --max-added) max_added="$2"; shift ;;
    -h|--help) sed -n '2,13s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; exit 0 ;;
    -*) cs_die "unknown argument: $1" ;;
    *) file="$1" ;;
  esac
  shift
done

bin="$CLOUDSHAPE_BUILD_DIR/bin"
work="$(mktemp -d)"
pids=()
# shellcheck disable=SC2317  # called by the EXIT trap
cleanup() {
  local pid
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  rm -rf "$work"
}
trap cleanup EXIT

if [[ -z "$file" ]]; then
  file="$CLOUDSHAPE_REPO/../shared/data/real/mosd_learn/learn5.pcd"
  if [[ ! -f "$file" ]]; then
    file="$work/scene.pcd"
    "$bin/cloudshape-synth" scene --layout row --count 3 --seed 2 -o "$file" >/dev/null
  fi
fi
topic=/bench/points
for stage in planes keypoints classifier solver; do
  "$bin/cloudshape-$stage" --domain "$domain" >"$work/$stage.log" 2>&1 &
  pids+=($!)
done
"$bin/cloudshape-ingest" --domain "$domain" --ros-topic "$topic" >"$work/ingest.log" 2>&1 &
pids+=($!)

status=0
header=1
for step in $steps; do
  out="$("$bin/cloudshape-bench-ros2" --domain "$domain" --topic "$topic" --frames "$frames" --point-step "$step" \
         "$file" 2>"$work/bench.err")" || { cat "$work/bench.err" >&2; cs_die "cloudshape-bench-ros2 failed"; }
  if ((header)); then sed -n '1,2p' <<<"$out"; header=0; fi
  sed -n '3p' <<<"$out"
  added="$(sed -n '4p' <<<"$out" | sed 's/.*"added_ms":\([-0-9.e]*\).*/\1/')"
  if [[ -n "$max_added" ]] && awk -v a="$added" -v m="$max_added" 'BEGIN {exit !(a > m)}'; then
    cs_log "point_step $step: PointCloud2 adds $added ms, more than $max_added ms"
    status=1
  fi
done
exit "$status"
