#!/usr/bin/env bash
# The DDS pipeline (five services, one host) against the in-process recognizer, on box clouds
# (30 x 20 x 10, cloudshape-synth). Prints Markdown tables.
#
#   tools/bench_dds.sh [--reps N] [--sizes "10000 100000 1000000"]       # latency, one cloud at a time
#   tools/bench_dds.sh --rates "5 10 20" [--clouds N] [--points P]        # steady-rate throughput
#   common: [--domain N] [--secure]
#
# --secure: every participant with DDS Security (a fresh tools/make-certs.sh PKI; docs/dds.md
# "DDS Security"), to measure what authentication and encryption cost.
# Latency: from the moment cloudshape-inject writes the sample (system clock in the header) to
# the moment cloudshape-echo takes the result: serialisation, transport, the five stages and
# every IDL <-> core conversion; clouds sent one at a time; median and p99 of --reps runs
# (p99 of 9 runs is their maximum). In-process: cloudshape-recognize's own timings_ms.total
# (the stages only, file reading excluded). Overhead: per cloud, the DDS latency minus the
# stage times the services measured for it (so load that varies between runs cancels out).
# Throughput: for each rate, --clouds clouds (default 100) of --points points (default 100 000)
# injected at that fixed rate; reports the rate sent and delivered (echo's receive times),
# the clouds lost, latency median / p99, and "sustained": every cloud delivered, delivered rate
# within 3% of the target, and no queue: median latency at most one period above the median of
# 10 clouds sent first at 1 cloud/s (the unloaded latency), p99 at most 3 x that median.
# The rates mode ends with each service's CPU time (user + system) per cloud over the rates: the
# stages share the host's cores, so their sum bounds the rate it can sustain (inject and echo,
# the sensor's and the consumer's side, not counted).
# Needs a build (build/bin).
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=bench_dds.sh
# shellcheck source-path=SCRIPTDIR source=lib/deps.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

reps=9
sizes="10000 100000 1000000"
rates=""
clouds=100
points=100000
domain=$((60 + RANDOM % 20))
secure=0
while (($#)); do
  case "$1" in
    --reps) reps="$2"; shift ;;
    --sizes) sizes="$2"; shift ;;
    --rates) rates="$2"; shift ;;
    --clouds) clouds="$2"; shift ;;
    --points) points="$2"; shift ;;
    --domain) domain="$2"; shift ;;
    --secure) secure=1 ;;
    -h|--help) sed -n '2,22s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) cs_die "unknown argument: $1" ;;
  esac
  shift
done

# shellcheck source-path=SCRIPTDIR source=lib/pipeline_run.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/pipeline_run.sh"
if ((secure)); then
  "$CLOUDSHAPE_REPO/tools/make-certs.sh" "$work/pki" 2>/dev/null
  export CLOUDSHAPE_SECURITY_DIR="$work/pki"  # read by launch.sh, echo and inject
fi

median() { sort -g | awk '{v[NR]=$1} END {if (NR==0) print "nan"; else if (NR%2) print v[(NR+1)/2]; else print (v[NR/2]+v[NR/2+1])/2}'; }
p99() { sort -g | awk '{v[NR]=$1} END {if (NR==0) print "nan"; else {i=int(NR*0.99); if (i<NR*0.99) i++; print v[i]}}'; }
box_cloud() {  # box_cloud POINTS -> path
  local cloud="$work/box_$1.pcd"
  [[ -f "$cloud" ]] || "$bin/cloudshape-synth" shape --shape box --dims 30,20,10 --points "$1" --seed 5 -o "$cloud" >/dev/null
  echo "$cloud"
}
inprocess_median() {  # inprocess_median FILE REPS: median timings_ms.total of cloudshape-recognize
  local -a files=()
  local i
  for ((i = 0; i < $2; i++)); do files+=("$1"); done
  "$bin/cloudshape-recognize" "${files[@]}" | sed -n 's/.*"total":\([0-9.eE+-]*\).*/\1/p' | median
}
# Echo's latency lines of the clouds with ids in [$1, $1 + $2).
latency_lines() { awk -v lo="$1" -v n="$2" '/latency_ms/ && $5 >= lo && $5 < lo + n' "$work/latency.txt"; }
# Per cloud with ids in [$1, $1 + $2): latency minus the stage times the services measured for
# that very cloud (echo's timings_ms.total): the DDS overhead, unaffected by load that changes
# between a separate in-process run and this one. Echo prints a cloud's result line and its
# latency line together, so the k-th of each belong to the same cloud.
overheads() {
  awk -v lo="$1" -v n="$2" '
    FNR == NR { if ($0 ~ /^\{/ && match($0, /"total":[0-9.eE+-]+/)) total[++r] = substr($0, RSTART + 8, RLENGTH - 8); next }
    /latency_ms/ { ++k; if ($5 >= lo && $5 < lo + n) print $3 - total[k] }' "$work/results.jsonl" "$work/latency.txt"
}
wait_for_results() {  # wait_for_results FIRST_ID N: until all came, or 30 s without a new one
  local got last=-1 still=0
  while :; do
    got="$(latency_lines "$1" "$2" | wc -l)"
    ((got < $2)) || return 0
    kill -0 "$echo_pid" 2>/dev/null || cs_die "cloudshape-echo ended early"
    if ((got == last)); then ((++still < 300)) || return 0; else still=0; last=$got; fi
    sleep 0.1
  done
}

# One echo for the whole run.
cs_start_pipeline "$domain" "$work/results.jsonl" "$work/latency.txt" --timeout 7200 --latency
next_id=0
# cpu_per_cloud FIRST_ID: each service's CPU ms per cloud since cpu_start.txt was read (when cloud
# FIRST_ID was next), and their sum.
cpu_per_cloud() {
  (($1 < next_id)) || return 0
  cs_service_cpu | awk -v n="$((next_id - $1))" -v cores="$(nproc)" '
    FNR == NR { start[$1] = $2; next }
    { ms = ($2 - start[$1]) / n; total += ms; line = line sprintf("%s %.1f, ", $1, ms) }
    END { printf "\nCPU per cloud (user + system, ms, %d clouds): %stotal %.1f; %d cores give %.0f ms a second, so at most %.0f clouds/s whatever the transport.\n",
                 n, line, total, cores, 1000 * cores, (total > 0 ? 1000 * cores / total : 0) }' "$work/cpu_start.txt" -
}

if [[ -z "$rates" ]]; then
  read -r -a size_list <<<"$sizes"
  printf '| points | in-process median (ms) | DDS inject->echo median (ms) | DDS p99 (ms) | ratio | overhead: DDS minus its own stage times, median (ms) |\n'
  printf '|---:|---:|---:|---:|---:|---:|\n'
  for n in "${size_list[@]}"; do
    cloud="$(box_cloud "$n")"
    inproc="$(inprocess_median "$cloud" "$reps")"
    # One cloud in flight at a time: the period is a few times the in-process time.
    rate="$(awk -v t="$inproc" 'BEGIN {p = (t * 4 + 200) / 1000; printf "%.3f", 1 / p}')"
    "$bin/cloudshape-inject" --domain "$domain" --rate "$rate" --count "$reps" --first-id "$next_id" "$cloud" 2>/dev/null
    wait_for_results "$next_id" "$reps"
    lat="$(latency_lines "$next_id" "$reps" | awk '{print $3}')"
    (($(wc -l <<<"$lat") == reps)) || cs_die "not every result came for $n points"
    dds="$(median <<<"$lat")"
    printf '| %s | %.1f | %.1f | %.1f | %.2f | %.1f |\n' "$n" "$inproc" "$dds" "$(p99 <<<"$lat")" \
      "$(awk -v a="$dds" -v b="$inproc" 'BEGIN {print a / b}')" "$(overheads "$next_id" "$reps" | median)"
    next_id=$((next_id + reps))
  done
  exit 0
fi

cloud="$(box_cloud "$points")"
inproc="$(inprocess_median "$cloud" 9)"
printf 'In-process recognizer, %s points: median %.1f ms per cloud, i.e. %.1f clouds/s on one core.\n\n' \
  "$points" "$inproc" "$(awk -v t="$inproc" 'BEGIN {print 1000 / t}')"
# The unloaded latency, 10 clouds at 1 cloud/s: a rate whose median stays within one period of
# it builds no queue.
"$bin/cloudshape-inject" --domain "$domain" --rate 1 --count 10 --first-id "$next_id" "$cloud" 2>/dev/null
wait_for_results "$next_id" 10
unloaded="$(latency_lines "$next_id" 10 | awk '{print $3}' | median)"
next_id=$((next_id + 10))
printf 'DDS inject->echo latency at 1 cloud/s: median %.1f ms.\n\n' "$unloaded"
printf '| target rate (clouds/s) | sent (clouds/s) | delivered (clouds/s) | lost | latency median (ms) | p99 (ms) | sustained |\n'
printf '|---:|---:|---:|---:|---:|---:|---|\n'
read -r -a rate_list <<<"$rates"
cs_service_cpu >"$work/cpu_start.txt"
first_rate_id=$next_id
best=none
failed=0
for rate in "${rate_list[@]}"; do
  sent="$("$bin/cloudshape-inject" --domain "$domain" --rate "$rate" --count "$clouds" --first-id "$next_id" "$cloud" 2>&1 \
          | sed -n 's/.*(\([0-9.]*\) clouds\/s).*/\1/p')"
  wait_for_results "$next_id" "$clouds"
  latency_lines "$next_id" "$clouds" | sort -k5,5n >"$work/step.txt"
  got="$(wc -l <"$work/step.txt")"
  delivered="$(awk '{t = $8 / 1e9; if (NR == 1 || t < t0) t0 = t; if (NR == 1 || t > t1) t1 = t}
    END {printf "%.2f", (NR > 1 && t1 > t0) ? (NR - 1) / (t1 - t0) : 0}' "$work/step.txt")"
  med="$(awk '{print $3}' "$work/step.txt" | median)"
  p99v="$(awk '{print $3}' "$work/step.txt" | p99)"
  sustained="$(awk -v got="$got" -v n="$clouds" -v rate="$rate" -v d="$delivered" -v m="$med" -v p="$p99v" -v u="$unloaded" \
    'BEGIN {print (got == n && d >= 0.97 * rate && d <= 1.03 * rate && m <= u + 1000 / rate && p <= 3 * u) ? "yes" : "no"}')"
  printf '| %s | %s | %s | %d | %.1f | %.1f | %s |\n' "$rate" "${sent:-?}" "$delivered" "$((clouds - got))" "$med" "$p99v" "$sustained"
  if [[ "$sustained" == yes ]]; then ((failed)) || best="$rate"; else failed=1; fi
  next_id=$((next_id + clouds))
done
printf '\nEvery rate up to %s clouds/s (of those tried, in order) sustained at %s points.\n' "$best" "$points"
cpu_per_cloud "$first_rate_id"
