#!/usr/bin/env bash
# Load test of the DDS pipeline (docs/reliability.md "Load"): 100k-point clouds through the
# five services.
#
#   tools/soak.sh [--seconds S] [--points N] [--rate HZ] [--overload N] [--max-growth-mb M] [--domain N]
#
# 1. Overload: N clouds (default 30) sent as fast as the pipeline takes them: the injector is
#    held back by the bounded queues (back-pressure), so this measures the capacity and the
#    memory each service needs when input outruns it.
# 2. Soak: S seconds (default 60) at HZ clouds per second (default: 80% of the capacity).
# Prints clouds sent, results, lost (sent - distinct results), clouds sent again, latency
# percentiles (inject -> echo), and each service's peak RSS in each half of the soak and
# under overload. Exit 1 when a cloud was lost, or a service's peak RSS grew by more than
# M MB (default 40) from the first half of the soak to the second. Needs a build.
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=soak.sh
# shellcheck source-path=SCRIPTDIR source=lib/deps.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

seconds=60
points=100000
rate=""
overload=30
max_growth_mb=40
domain=$((60 + RANDOM % 20))
while (($#)); do
  case "$1" in
    --seconds) seconds="$2"; shift ;;
    --points) points="$2"; shift ;;
    --rate) rate="$2"; shift ;;
    --overload) overload="$2"; shift ;;
    --max-growth-mb) max_growth_mb="$2"; shift ;;
    --domain) domain="$2"; shift ;;
    -h|--help) sed -n '2,14s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) cs_die "unknown argument: $1" ;;
  esac
  shift
done

# shellcheck source-path=SCRIPTDIR source=lib/pipeline_run.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/pipeline_run.sh"

# Four solids, so every stage does real work; distinct names, one per cloud sent.
declare -A dims=([box]='30,20,10' [cylinder]='10,30' [sphere]='12' [cone]='10,25')
for shape in box cylinder sphere cone; do
  "$bin/cloudshape-synth" shape --shape "$shape" --dims "${dims[$shape]}" --points "$points" --seed 7 \
    -o "$work/$shape.pcd" >/dev/null
done
clouds() {  # $1 = phase, $2 = count: links named <phase>_<i>_<shape>.pcd
  local i shapes=(box cylinder sphere cone) s
  for ((i = 0; i < $2; i++)); do
    s="${shapes[i % 4]}"
    ln -s "$work/$s.pcd" "$work/$1_${i}_$s.pcd"
    printf '%s\n' "$work/$1_${i}_$s.pcd"
  done
}
results_of() { grep -c "latency_ms.* $1_" "$work/latency.txt" || true; }

cs_start_pipeline "$domain" /dev/null "$work/latency.txt" --latency

# RSS of every service twice a second: "<phase> <seconds> <service> <kB>".
phase_file="$work/phase"
echo overload >"$phase_file"
sample_rss() {
  local pid name
  while :; do
    while read -r pid name; do
      printf '%s %s %s %s\n' "$(<"$phase_file")" "$SECONDS" "$name" \
        "$(awk '/^VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || echo 0)"
    done <"$CLOUDSHAPE_LOG_DIR/services.pids"
    sleep 0.5
  done
}
sample_rss >"$work/rss.txt" &
helper_pids+=($!)

# Sends the clouds and waits for every result; prints the seconds from the first result to
# the last (so the rate excludes start-up and filling the queues).
run_phase() {  # $1 = phase, $2 = count, $3 = rate (0: as fast as accepted)
  local files first="" n waited=0
  mapfile -t files < <(clouds "$1" "$2")
  "$bin/cloudshape-inject" --domain "$domain" --rate "$3" --resend-after 60 "${files[@]}" \
    2>"$work/inject_$1.log" &
  local inject_pid=$!
  while n="$(results_of "$1")"; ((n < $2)) && ((waited++ < 12000)); do
    [[ -n "$first" ]] || ((n == 0)) || first=$(date +%s.%N)
    sleep 0.05
  done
  wait "$inject_pid" || cs_log "cloudshape-inject exit status $? ($1)"
  awk -v s="${first:-0}" -v e="$(date +%s.%N)" 'BEGIN {printf "%.2f", e - s}'
}

overload_s="$(run_phase overload "$overload" 0)"
capacity="$(awk -v n="$overload" -v s="$overload_s" 'BEGIN {printf "%.2f", (n - 1) / s}')"
[[ -n "$rate" ]] || rate="$(awk -v c="$capacity" 'BEGIN {printf "%.2f", 0.8 * c}')"
soak_n="$(awk -v r="$rate" -v s="$seconds" 'BEGIN {printf "%d", r * s}')"
echo soak >"$phase_file"
soak_start=$SECONDS
soak_s="$(run_phase soak "$soak_n" "$rate")"
soak_end=$SECONDS

lost=0
for phase in overload soak; do
  sent="$(grep -c ': sent .* as cloud' "$work/inject_$phase.log" || true)"
  distinct="$(awk '/latency_ms/ {print $6}' "$work/latency.txt" | grep -c "^${phase}_" || true)"
  again="$(grep -c 'sending it again' "$work/inject_$phase.log" || true)"
  lost=$((lost + sent - distinct))
  printf '%s: %s clouds sent, %s results, %s lost, %s sent again\n' "$phase" "$sent" "$distinct" \
    "$((sent - distinct))" "$again"
done
printf 'capacity (overload, back-pressured): %s clouds/s of %s points; soak: %s clouds at %s/s in %s s\n' \
  "$capacity" "$points" "$soak_n" "$rate" "$soak_s"
awk '/latency_ms/ && $6 ~ /^soak_/ {print $3}' "$work/latency.txt" | sort -g | awk '
  function pct(p,  i) {i = int(NR * p + 0.5); if (i < 1) i = 1; return v[i]}
  {v[NR] = $1}
  END {
    if (NR == 0) {print "soak latency: no results"; exit}
    printf "soak latency ms: p50 %.1f  p90 %.1f  p99 %.1f  max %.1f  (%d clouds)\n", pct(0.5), pct(0.9), pct(0.99), v[NR], NR}'
# Sustainable: the median latency of the last quarter of the soak is not above the first's
# (a queue that grows would raise it).
awk '/latency_ms/ && $6 ~ /^soak_/ {print $3}' "$work/latency.txt" | awk '
  {v[NR] = $1}
  function median(from, to,  n, i, j, t, w) {
    n = 0; for (i = from; i <= to; i++) w[++n] = v[i]
    for (i = 2; i <= n; i++) {t = w[i]; for (j = i - 1; j > 0 && w[j] > t; j--) w[j + 1] = w[j]; w[j + 1] = t}
    return w[int((n + 1) / 2)]}
  END {if (NR >= 8) printf "soak latency median, first quarter %.1f ms, last quarter %.1f ms\n",
         median(1, int(NR / 4)), median(NR - int(NR / 4) + 1, NR)}'
# Memory growth: the peak RSS of the soak's second half against that of its first half
# (peaks, because the heap breathes by a few MB between two samples; a leak raises them).
half=$((soak_start + (soak_end - soak_start) / 2))
printf '| service | max RSS MB, 1st half of soak | max RSS MB, 2nd half | growth MB | max RSS MB under overload |\n'
printf '|---|---:|---:|---:|---:|\n'
growth_fail=0
while read -r _ name; do
  row="$(awk -v n="$name" -v h="$half" '
    $3 == n && $1 == "soak" {if ($2 < h) {if ($4 > a) a = $4} else if ($4 > b) b = $4}
    $3 == n && $1 == "overload" && $4 > o {o = $4}
    END {printf "%.1f %.1f %.1f %.1f", a / 1024, b / 1024, (b - a) / 1024, o / 1024}' "$work/rss.txt")"
  read -r a b g o <<<"$row"
  printf '| %s | %s | %s | %s | %s |\n' "$name" "$a" "$b" "$g" "$o"
  awk -v g="$g" -v lim="$max_growth_mb" 'BEGIN {exit !(g > lim)}' && growth_fail=1
done <"$CLOUDSHAPE_LOG_DIR/services.pids"
((lost == 0)) || cs_die "$lost cloud(s) lost"
((growth_fail == 0)) || cs_die "a service's memory grew by more than $max_growth_mb MB"
cs_log "PASS: no cloud lost, memory flat within $max_growth_mb MB"
