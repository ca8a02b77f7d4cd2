# Shared by tools/bench_dds.sh and tools/soak.sh (source it after lib/deps.sh, don't run it):
# a scratch folder, cloudshape-echo and the five services on one domain, and their clean-up.
# Sets: bin (build/bin), work (the scratch folder, removed on exit; the services log to
# $work/logs; cs_service_cpu reads their pids there), launch (tools/launch.sh), echo_pid, helper_pids (add the script's own
# background processes; they are ended first), launch_args (more `launch.sh start` arguments,
# e.g. --replicas ingest=2; empty).
# shellcheck shell=bash
# shellcheck disable=SC2034  # bin, work, launch: read by the scripts that source this

bin="$CLOUDSHAPE_BUILD_DIR/bin"
work="$(mktemp -d)"
export CLOUDSHAPE_LOG_DIR="$work/logs"
launch="$CLOUDSHAPE_REPO/tools/launch.sh"
echo_pid=""
helper_pids=()
launch_args=()

# shellcheck disable=SC2317  # called by the EXIT trap
cs_pipeline_cleanup() {
  local pid
  for pid in "${helper_pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  [[ -z "$echo_pid" ]] || kill -TERM "$echo_pid" 2>/dev/null || true
  "$launch" stop >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap cs_pipeline_cleanup EXIT

# cs_start_pipeline DOMAIN OUT ERR [ECHO OPTION...]: cloudshape-echo in the background (stdout
# to OUT, stderr to ERR), then the five services. Echo comes first: the services read input
# only once it listens, so no result is published before it is matched (results are VOLATILE).
cs_start_pipeline() {
  local domain="$1" out="$2" err="$3"
  shift 3
  # Checked here too: echo's own refusal would go to ERR, and the script stop without a word.
  if ! [[ "$domain" =~ ^[0-9]+$ ]] || ((domain > 232)); then
    cs_die "DDS domain \"$domain\" is not a domain id in 0..232"
  fi
  "$bin/cloudshape-echo" --domain "$domain" "$@" >"$out" 2>"$err" &
  echo_pid=$!
  "$launch" start --domain "$domain" "${launch_args[@]}" >/dev/null 2>&1
}

# cs_service_cpu: one line per service, "NAME MS": the CPU time (user + system) its processes have
# used so far, replicas summed, in milliseconds. Two readings apart, divided by the clouds sent
# between them, give each stage's CPU per cloud: what bounds the rate the host sustains.
cs_service_cpu() {
  local pids_file="$CLOUDSHAPE_LOG_DIR/services.pids" hz pid name
  hz="$(getconf CLK_TCK)"
  [[ -s "$pids_file" ]] || return 0
  while read -r pid name; do
    # Fields after the command name's closing parenthesis: utime and stime are the 12th and 13th.
    [[ -r "/proc/$pid/stat" ]] && sed 's/^.*) //' "/proc/$pid/stat" | awk -v n="$name" -v hz="$hz" '{print n, ($12 + $13) * 1000 / hz}'
  done <"$pids_file" | awk '{ms[$1] += $2} END {for (n in ms) print n, ms[n]}' | sort
}
