#!/usr/bin/env bash
# The MCAP benchmark (issue 12): reading speed of a recording of 640 x 480 depth frames, and its
# replay through the five services at the recorded 30 Hz. Prints Markdown tables.
#
#   tools/bench_mcap.sh [--frames N] [--rate HZ] [--domain N] [--skip-replay]
#
# Frames: cloudshape-synth scene (a table with three objects, 640 x 480 camera), three seeds used
# in turn, as PointCloud2 (float32 x y z rgb, 16 bytes a point, organized). Reading: the median
# of 3 reads of the whole file with cloudshape-mcap-bench read (container only, then with every
# PointCloud2 decoded into points), for uncompressed, lz4 and zstd chunks; MB = 10^6 bytes, of
# the file and of the messages it holds (the uncompressed recording's size). Replay:
# cloudshape-inject FILE.mcap at the recorded times, first to a bare subscriber of the raw-cloud
# topic (cloudshape-bench-hop sub: delivery alone), then through the five services; reports how
# far behind the recorded times the replay fell, the frames delivered, the results echo printed
# and when the last one came.
# Needs a build (build/bin) and about 3 GB in the temporary folder.
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=bench_mcap.sh
# shellcheck source-path=SCRIPTDIR source=lib/deps.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

frames=300
rate=30
domain=$((80 + RANDOM % 20))
replay=1
while (($#)); do
  case "$1" in
    --frames) frames="$2"; shift ;;
    --rate) rate="$2"; shift ;;
    --domain) domain="$2"; shift ;;
    --skip-replay) replay=0 ;;
    -h|--help) sed -n '2,13s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) cs_die "unknown argument: $1" ;;
  esac
  shift
done

# shellcheck source-path=SCRIPTDIR source=lib/pipeline_run.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/pipeline_run.sh"
for seed in 1 2 3; do
  "$bin/cloudshape-synth" scene --layout row --count 3 --seed "$seed" -o "$work/frame$seed.pcd" >/dev/null
done
json() { sed -n "s/.*\"$1\":\([^,}]*\).*/\1/p"; }

printf '| chunks | file (MB) | read, container: file MB/s | messages MB/s | frames/s | read and decode to points: messages MB/s | frames/s |\n'
printf '|---|---|---|---|---|---|---|\n'
messages_mb=""
for compression in none lz4 zstd; do
  rec="$work/frames_$compression.mcap"
  "$bin/cloudshape-mcap-bench" write "$work"/frame{1,2,3}.pcd --frames "$frames" --rate "$rate" \
    --compression "$compression" -o "$rec"
  plain="$("$bin/cloudshape-mcap-bench" read "$rec" --reps 3)"
  decoded="$("$bin/cloudshape-mcap-bench" read "$rec" --reps 3 --decode)"
  [[ -n "$messages_mb" ]] || messages_mb="$(json mb <<<"$plain")"
  awk -v c="$compression" -v mb="$(json mb <<<"$plain")" -v all="$messages_mb" -v f="$frames" \
      -v t="$(json median_s <<<"$plain")" -v td="$(json median_s <<<"$decoded")" \
      'BEGIN {printf "| %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f |\n", c, mb, mb / t, all / t, f / t, all / td, f / td}'
  [[ "$compression" == none ]] || rm -f "$rec"
done
((replay)) || exit 0

echo
rec="$work/frames_none.mcap"
recorded="$(awk -v n="$frames" -v r="$rate" 'BEGIN {printf "%.1f", (n - 1) / r}')"
"$bin/cloudshape-bench-hop" sub --domain "$domain" --count "$frames" >"$work/hop.txt" 2>&1 &
hop_pid=$!
helper_pids+=("$hop_pid")
"$bin/cloudshape-inject" --domain "$domain" --resend-after 0 "$rec" 2>"$work/inject_hop.err" || true
wait "$hop_pid" || true
delivered="$(sed -n 's/.*write -> taken.*median *\([0-9.]*\) ms.*max *\([0-9.]*\) *(n=\([0-9]*\)).*/\3 \1 \2/p' "$work/hop.txt")"
read -r hop_n hop_median hop_max <<<"${delivered:-0 nan nan}"
hop_behind="$(sed -n 's/.*at most \([0-9.]*\) s behind.*/\1/p' "$work/inject_hop.err")"
printf '| replay to | frames | recorded span (s) | most behind the recorded times (s) | frames delivered | write -> taken median / max (ms) |\n'
printf '|---|---|---|---|---|---|\n'
printf '| a bare raw-cloud subscriber | %d | %s | %s | %s | %s / %s |\n\n' "$frames" "$recorded" "${hop_behind:-nan}" \
  "$hop_n" "$hop_median" "$hop_max"

cs_start_pipeline "$domain" "$work/results.jsonl" "$work/echo.err" --count "$frames" --timeout 1800 --latency
start=$(date +%s.%N)
"$bin/cloudshape-inject" --domain "$domain" "$rec" 2>"$work/inject.err" || true
sent_done=$(date +%s.%N)
wait "$echo_pid" || true
echo_pid=""
done_at=$(date +%s.%N)
sent="$(grep -c ' sent frames_none.mcap#' "$work/inject.err" || true)"
behind="$(sed -n 's/.*at most \([0-9.]*\) s behind.*/\1/p' "$work/inject.err")"
results="$(grep -c '"source"' "$work/results.jsonl" || true)"
printf '| replay through | frames | recorded span (s) | most behind the recorded times (s) | frames sent | results | last result after (s) | frames recognised per s |\n'
printf '|---|---|---|---|---|---|---|---|\n'
awk -v f="$frames" -v span="$recorded" -v behind="${behind:-nan}" -v sent="$sent" -v res="$results" \
    -v s="$start" -v d="$done_at" \
    'BEGIN {printf "| the five services | %d | %s | %s | %d | %d | %.1f | %.1f |\n", f, span, behind, sent, res, d - s, res / (d - s)}'
printf '\ninject finished sending after %.1f s.\n' "$(awk -v s="$start" -v i="$sent_done" 'BEGIN {print i - s}')"
