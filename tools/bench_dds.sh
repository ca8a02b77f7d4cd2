#!/usr/bin/env bash
# The DDS pipeline (five services, one host) against the in-process recognizer, on box clouds
# (30 x 20 x 10, cloudshape-synth). Prints Markdown tables.
#
#   tools/bench_dds.sh [--reps N] [--sizes "10000 100000 1000000"]       # latency, one cloud at a time
#   tools/bench_dds.sh --rates "5 10 20" [--clouds N] [--points P]        # steady-rate throughput
#   common: [--domain N]
#
# Latency: from the moment cloudshape-inject writes the sample (system clock in the header) to
# the moment cloudshape-echo takes the result: serialisation, transport, the five stages and
# every IDL <-> core conversion; clouds sent one at a time; median and p99 of --reps runs
# (p99 of 9 runs is their maximum). In-process: cloudshape-recognize's own timings_ms.total
# (the stages only, file reading excluded).
# Throughput: for each rate, --clouds clouds (default 100) of --points points (default 100 000)
# injected at that fixed rate; reports the rate sent and delivered (echo's receive times),
# the clouds lost, latency median / p99, and "sustained": every cloud delivered, delivered rate
# within 3% of the target and no queue building up (the last quarter's median latency at most
# 1.5 x the first quarter's + 20 ms). Needs a build (build/bin).
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
while (($#)); do
  case "$1" in
    --reps) reps="$2"; shift ;;
    --sizes) sizes="$2"; shift ;;
    --rates) rates="$2"; shift ;;
    --clouds) clouds="$2"; shift ;;
    --points) points="$2"; shift ;;
    --domain) domain="$2"; shift ;;
    -h|--help) sed -n '2,20s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; exit 0 ;;
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

# One echo for the whole run, started before the services: they read input only once it
# listens, so no result can be published before it is matched (results are VOLATILE).
"$bin/cloudshape-echo" --domain "$domain" --timeout 7200 --latency >/dev/null 2>"$work/latency.txt" &
echo_pid=$!
"$launch" start --domain "$domain" >/dev/null 2>&1
next_id=0

if [[ -z "$rates" ]]; then
  read -r -a size_list <<<"$sizes"
  printf '| points | in-process median (ms) | DDS inject->echo median (ms) | DDS p99 (ms) | overhead (ms) | ratio |\n'
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
    printf '| %s | %.1f | %.1f | %.1f | %.1f | %.2f |\n' "$n" "$inproc" "$dds" "$(p99 <<<"$lat")" \
      "$(awk -v a="$dds" -v b="$inproc" 'BEGIN {print a - b}')" "$(awk -v a="$dds" -v b="$inproc" 'BEGIN {print a / b}')"
    next_id=$((next_id + reps))
  done
  exit 0
fi

cloud="$(box_cloud "$points")"
inproc="$(inprocess_median "$cloud" 9)"
printf 'In-process recognizer, %s points: median %.1f ms per cloud, i.e. %.1f clouds/s on one core.\n\n' \
  "$points" "$inproc" "$(awk -v t="$inproc" 'BEGIN {print 1000 / t}')"
printf '| target rate (clouds/s) | sent (clouds/s) | delivered (clouds/s) | lost | latency median (ms) | p99 (ms) | sustained |\n'
printf '|---:|---:|---:|---:|---:|---:|---|\n'
read -r -a rate_list <<<"$rates"
best=none
for rate in "${rate_list[@]}"; do
  sent="$("$bin/cloudshape-inject" --domain "$domain" --rate "$rate" --count "$clouds" --first-id "$next_id" "$cloud" 2>&1 \
          | sed -n 's/.*(\([0-9.]*\) clouds\/s).*/\1/p')"
  wait_for_results "$next_id" "$clouds"
  latency_lines "$next_id" "$clouds" | sort -k5,5n >"$work/step.txt"
  got="$(wc -l <"$work/step.txt")"
  read -r delivered med p99v sustained < <(awk -v n="$clouds" -v rate="$rate" '
    function med(a, lo, hi,   m, i, j, t, k) {  # median of a[lo..hi] (copied, sorted)
      delete b; m = 0; for (i = lo; i <= hi; i++) b[++m] = a[i]
      for (i = 2; i <= m; i++) { t = b[i]; for (j = i - 1; j >= 1 && b[j] > t; j--) b[j + 1] = b[j]; b[j + 1] = t }
      k = int((m + 1) / 2); return (m % 2) ? b[k] : (b[k] + b[k + 1]) / 2 }
    { lat[NR] = $3; t = $8 / 1e9; if (NR == 1 || t < t0) t0 = t; if (NR == 1 || t > t1) t1 = t }
    END {
      got = NR; q = int(got / 4); if (q < 1) q = 1
      delivered = (got > 1 && t1 > t0) ? (got - 1) / (t1 - t0) : 0
      first = med(lat, 1, q); last = med(lat, got - q + 1, got); all = med(lat, 1, got)
      ok = (got == n && delivered >= 0.97 * rate && last <= 1.5 * first + 20) ? "yes" : "no"
      printf "%.2f %.1f nan %s\n", delivered, all, ok }' "$work/step.txt")
  p99v="$(awk '{print $3}' "$work/step.txt" | p99)"
  printf '| %s | %s | %s | %d | %s | %.1f | %s |\n' "$rate" "${sent:-?}" "$delivered" "$((clouds - got))" "$med" "$p99v" "$sustained"
  [[ "$sustained" != yes ]] || best="$rate"
  next_id=$((next_id + clouds))
done
printf '\nHighest sustained rate tried: %s clouds/s of %s points.\n' "$best" "$points"
