#!/usr/bin/env bash
# Latency of the DDS pipeline (inject -> echo, five services, one host) against the
# in-process recognizer, for box clouds of 10k, 100k and 1M points. Prints a Markdown table.
#
#   tools/bench_dds.sh [--reps N] [--sizes "10000 100000 1000000"] [--domain N] [--secure]
#
# --secure: every participant with DDS Security (a fresh tools/make-certs.sh PKI; README
# "DDS Security"), to measure what authentication and encryption cost.
# DDS latency: from the moment cloudshape-inject writes the sample (system clock in the
# header) to the moment cloudshape-echo takes the result: serialisation, transport, the
# five stages and every IDL <-> core conversion. Clouds are sent one at a time (--rate low
# enough that none queues). In-process: cloudshape-recognize's own timings_ms.total (the
# stages only, file reading excluded). Medians of --reps runs. Needs a build (build/bin).
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=bench_dds.sh
# shellcheck source-path=SCRIPTDIR source=lib/deps.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

reps=9
sizes="10000 100000 1000000"
domain=$((60 + RANDOM % 20))
secure=0
while (($#)); do
  case "$1" in
    --reps) reps="$2"; shift ;;
    --sizes) sizes="$2"; shift ;;
    --domain) domain="$2"; shift ;;
    --secure) secure=1 ;;
    -h|--help) sed -n '2,13s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) cs_die "unknown argument: $1" ;;
  esac
  shift
done

bin="$CLOUDSHAPE_BUILD_DIR/bin"
work="$(mktemp -d)"
export CLOUDSHAPE_LOG_DIR="$work/logs"
launch="$CLOUDSHAPE_REPO/tools/launch.sh"
echo_pid=""
# shellcheck disable=SC2317  # called by the EXIT trap
cleanup() {
  [[ -z "$echo_pid" ]] || kill -TERM "$echo_pid" 2>/dev/null || true
  "$launch" stop >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT
if ((secure)); then
  "$CLOUDSHAPE_REPO/tools/make-certs.sh" "$work/pki" 2>/dev/null
  export CLOUDSHAPE_SECURITY_DIR="$work/pki"  # read by launch.sh, echo and inject
fi

median() { sort -g | awk '{v[NR]=$1} END {if (NR==0) print "nan"; else if (NR%2) print v[(NR+1)/2]; else print (v[NR/2]+v[NR/2+1])/2}'; }

read -r -a size_list <<<"$sizes"
total=$((reps * ${#size_list[@]}))
# One echo for the whole run, started before the services: they read input only once it
# listens, so no result can be published before it is matched (results are VOLATILE).
"$bin/cloudshape-echo" --domain "$domain" --count "$total" --timeout 1800 --latency \
  >/dev/null 2>"$work/latency.txt" &
echo_pid=$!
"$launch" start --domain "$domain" >/dev/null 2>&1
printf '| points | in-process median (ms) | DDS inject->echo median (ms) | overhead (ms) |\n'
printf '|---:|---:|---:|---:|\n'
for n in "${size_list[@]}"; do
  cloud="$work/box_$n.pcd"
  "$bin/cloudshape-synth" shape --shape box --dims 30,20,10 --points "$n" --seed 5 -o "$cloud" >/dev/null
  files=()
  for ((i = 0; i < reps; i++)); do files+=("$cloud"); done
  inproc="$("$bin/cloudshape-recognize" "${files[@]}" | sed -n 's/.*"total":\([0-9.eE+-]*\).*/\1/p' | median)"
  # One cloud in flight at a time: the period is a few times the in-process time.
  rate="$(awk -v t="$inproc" 'BEGIN {p = (t * 4 + 200) / 1000; printf "%.3f", 1 / p}')"
  "$bin/cloudshape-inject" --domain "$domain" --rate "$rate" "${files[@]}" 2>/dev/null
  waited=0
  while (($(grep -c "box_$n.pcd" "$work/latency.txt" || true) < reps)); do
    kill -0 "$echo_pid" 2>/dev/null || cs_die "cloudshape-echo ended early"
    ((waited++ < 6000)) || cs_die "not every result came for $n points"
    sleep 0.1
  done
  dds="$(awk -v f="box_$n.pcd" '/latency_ms/ && $6 == f {print $3}' "$work/latency.txt" | median)"
  printf '| %s | %.1f | %.1f | %.1f |\n' "$n" "$inproc" "$dds" "$(awk -v a="$dds" -v b="$inproc" 'BEGIN {print a - b}')"
done
