#!/usr/bin/env bash
# The replay benchmark (issue 12): a recording of N 640 x 480 depth frames at R Hz replayed at its
# recorded times by cloudshape-inject, to a bare raw-cloud subscriber, then through the five
# services to cloudshape-echo. Prints Markdown tables: how far the replay fell behind, frames
# delivered (taken by ingest) and recognised (every object as cloudshape-recognize finds it in
# that frame), the rate sustained, latency percentiles, and where the time went: each process's
# CPU seconds (from /proc) and each service's stage time per message (from its log), all of
# them per frame beside the CPU cloudshape-recognize --threads 1 needs for the same frames in
# one process, the loopback traffic per frame and the machine's load average.
#
#   tools/bench_replay.sh [--frames N] [--rate HZ] [--compression none|lz4|zstd] [--domain N] [--no-bare]
#                         [--replicas STAGE=N]...   # as tools/launch.sh start (ingest=2: two ingest lanes)
#
# DDS traffic must meet nobody else's: run it in a private network namespace,
#   unshare -rn sh -c 'ip link set lo up; tools/bench_replay.sh'
# Frames: lib/replay_recording.sh (three cloudshape-synth scenes in turn). Needs a build
# (build/bin) and 1.5 GB in the temporary folder per 300 uncompressed frames.
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=bench_replay.sh
# shellcheck source-path=SCRIPTDIR source=lib/deps.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

frames=300
rate=30
compression=none
domain=$((150 + RANDOM % 60))
bare=1
replicas=()
subscribers=1
while (($#)); do
  case "$1" in
    --frames) frames="$2"; shift ;;
    --rate) rate="$2"; shift ;;
    --compression) compression="$2"; shift ;;
    --domain) domain="$2"; shift ;;
    --no-bare) bare=0 ;;
    --replicas) replicas+=(--replicas "$2"); [[ "$2" != ingest=* ]] || subscribers="${2#ingest=}"; shift ;;
    -h|--help) sed -n '2,16s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) cs_die "unknown argument: $1" ;;
  esac
  shift
done
[[ "$frames" =~ ^[1-9][0-9]*$ ]] || cs_die "--frames $frames: expected a positive whole number"
[[ "$compression" =~ ^(none|lz4|zstd)$ ]] || cs_die "--compression $compression: expected none, lz4 or zstd"

# shellcheck source-path=SCRIPTDIR source=lib/pipeline_run.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/pipeline_run.sh"
# shellcheck source-path=SCRIPTDIR source=lib/replay_recording.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/replay_recording.sh"

# The machine's load average (1, 5, 15 min): CPU per frame is the stable figure on a shared
# machine, rates are not.
load() { cut -d' ' -f1-3 /proc/loadavg; }
load_start="$(load)"
rec="$work/replay.mcap"
cs_replay_recording "$rec" "$frames" "$rate" "$compression"
recorded="$(awk -v n="$frames" -v r="$rate" 'BEGIN {printf "%.1f", (n - 1) / r}')"
# What the services must find in frame k: what cloudshape-recognize finds in that frame file.
shapes() { grep -o '"shape": *"[a-z_]*"' | sed 's/.*"\([a-z_]*\)"$/\1/' | paste -sd, -; }
for seed in 1 2 3; do
  "$bin/cloudshape-recognize" "$work/frame$seed.pcd" | shapes >"$work/expected$seed.txt"
done
cs_log "expected per frame: $(cat "$work"/expected{1,2,3}.txt | paste -sd' ')"

if ((bare)); then
  "$bin/cloudshape-bench-hop" sub --domain "$domain" --count "$frames" >"$work/hop.txt" 2>&1 &
  hop_pid=$!
  helper_pids+=("$hop_pid")
  "$bin/cloudshape-inject" --domain "$domain" --resend-after 0 "$rec" 2>"$work/inject_hop.err" || true
  helper_pids=()
  wait "$hop_pid" || true
  delivered="$(sed -n 's/.*write -> taken.*median *\([0-9.]*\) ms.*max *\([0-9.]*\) *(n=\([0-9]*\)).*/\3 \1 \2/p' "$work/hop.txt")"
  read -r hop_n hop_median hop_max <<<"${delivered:-0 nan nan}"
  hop_behind="$(sed -n 's/.*at most \([0-9.]*\) s behind.*/\1/p' "$work/inject_hop.err")"
  printf '| replay to | frames | recorded span (s) | most behind the recorded times (s) | frames delivered | write -> taken median / max (ms) |\n'
  printf '|---|---|---|---|---|---|\n'
  printf '| a bare raw-cloud subscriber | %d | %s | %s | %s | %s / %s |\n\n' "$frames" "$recorded" \
    "${hop_behind:-nan}" "$hop_n" "$hop_median" "$hop_max"
fi

# CPU seconds (user + system) of a process so far, from /proc.
cpu_s() { awk -v hz="$(getconf CLK_TCK)" '{print ($14 + $15) / hz}' "/proc/$1/stat" 2>/dev/null || echo 0; }
# CPU seconds (user + system) of the children this shell waited for so far (bash's `times`,
# run in this shell: in a pipe or $(...) it would see a subshell's children, none).
children_cpu_s() {
  times >"$work/times.txt"
  tail -1 "$work/times.txt" | awk '{n = 0; for (i = 1; i <= 2; i++) {split($i, t, /[ms]/); n += t[1] * 60 + t[2]}; print n}'
}
# Bytes through the loopback interface so far: the traffic of this network namespace.
loopback_bytes() { awk -F'[: ]+' '$2 == "lo" {print $3}' /proc/net/dev; }

# The same frames in one process, single-threaded: the recognition's own CPU per frame, the
# program's start-up (one frame) taken off.
inprocess_ms="$(
  files=()
  for ((k = 0; k < 5; k++)); do files+=("$work"/frame{1,2,3}.pcd); done
  ("$bin/cloudshape-recognize" --threads 1 "$work/frame1.pcd" >/dev/null; children_cpu_s) >"$work/cpu1.txt"
  ("$bin/cloudshape-recognize" --threads 1 "$work/frame1.pcd" "${files[@]}" >/dev/null; children_cpu_s) >"$work/cpu16.txt"
  awk -v a="$(cat "$work/cpu1.txt")" -v b="$(cat "$work/cpu16.txt")" -v n="${#files[@]}" \
    'BEGIN {printf "%.1f", 1000 * (b - a) / n}'
)"

launch_args=("${replicas[@]}")
lo_before="$(loopback_bytes)"
cs_start_pipeline "$domain" "$work/results.jsonl" "$work/echo.err" --count "$frames" --timeout 900 --latency
"$bin/cloudshape-inject" --domain "$domain" --subscribers "$subscribers" --result-timeout 300 "$rec" 2>"$work/inject.err" &
inject_pid=$!
helper_pids+=("$inject_pid")
declare -A cpu=()
names=(inject echo)
# Sampled just before each process ends (inject and echo exit once every result came; the
# services are sampled as soon as echo has printed the last result).
while kill -0 "$inject_pid" 2>/dev/null; do
  # A sample taken as it exits reads nothing (0): keep the one before.
  c="$(cpu_s "$inject_pid")"
  [[ "$c" == 0 ]] || cpu[inject]="$c"
  c="$(cpu_s "$echo_pid")"
  [[ "$c" == 0 ]] || cpu[echo]="$c"
  sleep 0.2
done
wait "$inject_pid" || true
wait "$echo_pid" || true
echo_pid=""
while read -r pid name; do
  cpu[$name]="$(cpu_s "$pid")"
  names+=("$name")
done <"$CLOUDSHAPE_LOG_DIR/services.pids"
lo_mb="$(awk -v a="$lo_before" -v b="$(loopback_bytes)" -v f="$frames" 'BEGIN {printf "%.1f", (b - a) / 1e6 / f}')"

sent="$(grep -c ' sent replay.mcap#' "$work/inject.err" || true)"
behind="$(sed -n 's/.*at most \([0-9.]*\) s behind.*/\1/p' "$work/inject.err")"
taken="$(sed -n 's/.*cloud \([0-9]*\) (replay\.mcap#[0-9]*) object 0:.*/\1/p' "$CLOUDSHAPE_LOG_DIR"/ingest*.log |
  sort -u | wc -l)"
results="$(grep -c '"source"' "$work/results.jsonl" || true)"
recognised=0
while IFS= read -r line; do
  k="$(sed -n 's/.*"source": *"replay\.mcap#\([0-9]*\)".*/\1/p' <<<"$line")"
  [[ -n "$k" ]] || continue
  [[ "$(shapes <<<"$line")" == "$(cat "$work/expected$((k % 3 + 1)).txt")" ]] && recognised=$((recognised + 1))
done <"$work/results.jsonl"
# First to last result: seconds, from the receive times (ns) echo printed.
span_s="$(sed -n 's/.*received_ns \([0-9]*\).*/\1/p' "$work/echo.err" | sort -n |
  awk 'NR == 1 {f = $1} {l = $1} END {printf "%.3f", NR ? (l - f) / 1e9 : 0}')"
read -r p50 p90 p99 pmax < <(sed -n 's/.*latency_ms \([0-9.]*\) .*/\1/p' "$work/echo.err" | cs_percentiles)

printf '| replay through | frames | recorded span (s) | most behind the recorded times (s) | frames sent | delivered | results | recognised | sustained (frames/s) | latency p50 / p90 / p99 / max (ms) |\n'
printf '|---|---|---|---|---|---|---|---|---|---|\n'
awk -v f="$frames" -v span="$recorded" -v behind="${behind:-nan}" -v sent="$sent" -v taken="$taken" \
    -v res="$results" -v ok="$recognised" -v s="$span_s" \
    -v lat="$p50 / $p90 / $p99 / $pmax" \
    'BEGIN {printf "| the five services | %d | %s | %s | %d | %d | %d | %d | %.1f | %s |\n",
                   f, span, behind, sent, taken, res, ok, (s > 0 ? (res - 1) / s : 0), lat}'

echo
printf '| process | CPU (s) | CPU per frame (ms) | stage time per message p50 / p90 (ms) | messages |\n'
printf '|---|---|---|---|---|\n'
total_s=0
for name in "${names[@]}"; do
  stage="- | -"
  total_s="$(awk -v t="$total_s" -v c="${cpu[$name]:-0}" 'BEGIN {print t + c}')"
  if [[ "$name" != inject && "$name" != echo ]]; then
    log="$CLOUDSHAPE_LOG_DIR/$name.log"
    n="$(grep -c ': done in \|: error passed on in ' "$log" || true)"
    read -r s50 s90 _ _ < <(sed -n 's/.*: \(done\|error passed on\) in \([0-9.]*\) ms.*/\2/p' "$log" | cs_percentiles)
    stage="$s50 / $s90 | $n"
  fi
  awk -v name="$name" -v c="${cpu[$name]:-0}" -v f="$frames" -v stage="$stage" \
    'BEGIN {printf "| %s | %.1f | %.1f | %s |\n", name, c, 1000 * c / f, stage}'
done
awk -v c="$total_s" -v f="$frames" 'BEGIN {printf "| all of them | %.1f | %.1f | - | - |\n", c, 1000 * c / f}'
awk -v ms="$inprocess_ms" 'BEGIN {printf "| in one process (cloudshape-recognize --threads 1, the same frames) | - | %.1f | - | - |\n", ms}'
echo
awk -v c="$total_s" -v f="$frames" -v ms="$inprocess_ms" -v lo="$lo_mb" -v a="$load_start" -v b="$(load)" \
  'BEGIN {printf "CPU per frame: %.1f ms for the services, inject and echo, %.1f ms in one process (%.1f ms more); loopback traffic %s MB per frame; load average (1, 5, 15 min) %s at the start, %s at the end.\n",
          1000 * c / f, ms, 1000 * c / f - ms, lo, a, b}'
