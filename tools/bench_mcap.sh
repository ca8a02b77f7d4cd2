#!/usr/bin/env bash
# The MCAP reading benchmark (issue 12): reading speed of a recording of 640 x 480 depth frames.
# Prints a Markdown table. Its replay through the services: tools/bench_replay.sh.
#
#   tools/bench_mcap.sh [--frames N] [--rate HZ]
#
# Frames: lib/replay_recording.sh (cloudshape-synth scenes, three seeds in turn, as PointCloud2
# float32 x y z rgb, 16 bytes a point, organized). Reading: the median of 3 reads of the whole
# file with cloudshape-mcap-bench read (container only, then with every PointCloud2 decoded into
# points), for uncompressed, lz4 and zstd chunks; MB = 10^6 bytes, of the file and of the
# messages it holds (the uncompressed recording's size). Seeking: the median of 3 reads of the
# last 10 messages (--start N-10, through the index) of each recording.
# Needs a build (build/bin) and about 1.5 GB in the temporary folder.
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=bench_mcap.sh
# shellcheck source-path=SCRIPTDIR source=lib/deps.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

frames=300
rate=30
while (($#)); do
  case "$1" in
    --frames) frames="$2"; shift ;;
    --rate) rate="$2"; shift ;;
    -h|--help) sed -n '2,11s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) cs_die "unknown argument: $1" ;;
  esac
  shift
done

# shellcheck source-path=SCRIPTDIR source=lib/pipeline_run.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/pipeline_run.sh"
# shellcheck source-path=SCRIPTDIR source=lib/replay_recording.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/replay_recording.sh"
json() { sed -n "s/.*\"$1\":\([^,}]*\).*/\1/p"; }

printf '| chunks | file (MB) | read, container: file MB/s | messages MB/s | frames/s | read and decode to points: messages MB/s | frames/s |\n'
printf '|---|---|---|---|---|---|---|\n'
messages_mb=""
seeks=()
for compression in none lz4 zstd; do
  rec="$work/frames_$compression.mcap"
  cs_replay_recording "$rec" "$frames" "$rate" "$compression"
  plain="$("$bin/cloudshape-mcap-bench" read "$rec" --reps 3)"
  decoded="$("$bin/cloudshape-mcap-bench" read "$rec" --reps 3 --decode)"
  [[ -n "$messages_mb" ]] || messages_mb="$(json mb <<<"$plain")"
  awk -v c="$compression" -v mb="$(json mb <<<"$plain")" -v all="$messages_mb" -v f="$frames" \
      -v t="$(json median_s <<<"$plain")" -v td="$(json median_s <<<"$decoded")" \
      'BEGIN {printf "| %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f |\n", c, mb, mb / t, all / t, f / t, all / td, f / td}'
  from=$((frames > 10 ? frames - 10 : 0))
  seek="$("$bin/cloudshape-mcap-bench" read "$rec" --reps 3 --start "$from")"
  seeks+=("$(awk -v c="$compression" -v n="$((frames - from))" -v t="$(json median_s <<<"$seek")" \
    -v used="$(json index_used <<<"$seek")" -v whole="$(json median_s <<<"$plain")" \
    'BEGIN {printf "| %s | %d | %.1f | %.0f | %s |", c, n, 1000 * t, 1000 * whole, used}')")
  rm -f "$rec"
done
printf '\n| chunks | last messages read (--start) | seek and read them (ms) | the whole file (ms) | index used |\n'
printf '|---|---|---|---|---|\n'
printf '%s\n' "${seeks[@]}"
