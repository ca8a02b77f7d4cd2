#!/usr/bin/env bash
# Starts / stops the five cloudshape DDS services natively, logs in files (one per service).
#
#   tools/launch.sh start [--domain N] [--replicas STAGE=N]... [--config FILE] [--security DIR]
#                         [--ros-topic TOPIC]...    # ingest also reads ROS 2 PointCloud2 on TOPIC
#   tools/launch.sh stop            # SIGTERM each service, SIGKILL after 30 s
#   tools/launch.sh status          # a few status samples (cloudshape-echo --status)
#   tools/launch.sh run [...]       # start, then stop on Ctrl-C (foreground)
#
# Stages: ingest planes keypoints classifier solver. `--replicas keypoints=2` runs two
# keypoints replicas (lanes 0 and 1, each cloud to exactly one) and makes planes wait for both.
# --security DIR (else CLOUDSHAPE_SECURITY_DIR): DDS Security with the PKI tools/make-certs.sh
# made in DIR; echo, inject and `status` then need it too (export CLOUDSHAPE_SECURITY_DIR).
# Logs and pids: $CLOUDSHAPE_LOG_DIR, default build/logs/. Binaries: build/bin/
# (CLOUDSHAPE_BUILD_DIR). Domain: --domain, else CLOUDSHAPE_DOMAIN, else 0.
# Services read input only once their output has a subscriber: start cloudshape-echo (or any
# subscriber of cloudshape_result) and cloudshape-inject waits until the chain is up.
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=launch.sh
# shellcheck source-path=SCRIPTDIR source=lib/deps.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

STAGES=(ingest planes keypoints classifier solver)
bin="$CLOUDSHAPE_BUILD_DIR/bin"
logs="${CLOUDSHAPE_LOG_DIR:-$CLOUDSHAPE_BUILD_DIR/logs}"
pids="$logs/services.pids"

usage() { sed -n '2,18s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; }

upstream_of() {  # the stage that publishes what $1 reads
  case "$1" in
    planes) echo ingest ;; keypoints) echo planes ;; classifier) echo keypoints ;;
    solver) echo classifier ;; *) echo "" ;;
  esac
}

start() {
  local domain="${CLOUDSHAPE_DOMAIN:-0}" config="" security="${CLOUDSHAPE_SECURITY_DIR:-}" spec stage n
  declare -A replicas=()
  local -a ros=()
  while (($#)); do
    case "$1" in
      --domain) domain="$2"; shift ;;
      --config) config="$2"; shift ;;
      --security) security="$2"; shift ;;
      --ros-topic) ros+=(--ros-topic "$2"); shift ;;
      --replicas)
        spec="$2"; stage="${spec%%=*}"; n="${spec#*=}"
        [[ " ${STAGES[*]} " == *" $stage "* && "$n" =~ ^[1-9][0-9]*$ ]] || cs_die "bad --replicas $spec"
        replicas[$stage]="$n"; shift ;;
      *) usage >&2; cs_die "unknown argument: $1" ;;
    esac
    shift
  done
  [[ ! -s "$pids" ]] || cs_die "services already started ($pids); run: tools/launch.sh stop"
  mkdir -p "$logs"
  : >"$pids"
  local -a common=(--domain "$domain")
  [[ -z "$config" ]] || common+=(--config "$config")
  [[ -z "$security" ]] || common+=(--security "$security")
  local s lanes lane down subs
  for s in "${STAGES[@]}"; do
    [[ -x "$bin/cloudshape-$s" ]] || cs_die "$bin/cloudshape-$s not built (cmake --build $CLOUDSHAPE_BUILD_DIR)"
    lanes="${replicas[$s]:-1}"
    # Wait for every replica of the next stage before reading input.
    subs=1
    for down in "${STAGES[@]}"; do
      [[ "$(upstream_of "$down")" == "$s" ]] && subs="${replicas[$down]:-1}"
    done
    local -a own=()
    [[ "$s" != ingest ]] || own=("${ros[@]}")
    for ((lane = 0; lane < lanes; lane++)); do
      local name="$s"
      ((lanes == 1)) || name="$s-$lane"
      "$bin/cloudshape-$s" "${common[@]}" "${own[@]}" --lane "$lane" --lanes "$lanes" --subscribers "$subs" \
        >>"$logs/$name.log" 2>&1 &
      printf '%s %s\n' "$!" "$name" >>"$pids"
      cs_log "started $name (pid $!, domain $domain, security ${security:-off}, log $logs/$name.log)"
    done
  done
}

stop() {
  [[ -s "$pids" ]] || { cs_log "nothing to stop ($pids is empty)"; return 0; }
  local pid name waited status=0
  while read -r pid name; do kill -TERM "$pid" 2>/dev/null || true; done <"$pids"
  while read -r pid name; do
    waited=0
    while kill -0 "$pid" 2>/dev/null && ((waited < 300)); do sleep 0.1; waited=$((waited + 1)); done
    if kill -0 "$pid" 2>/dev/null; then
      kill -KILL "$pid" 2>/dev/null || true
      cs_log "$name (pid $pid) did not stop in 30 s: killed"
      status=1
    else
      cs_log "stopped $name (pid $pid)"
    fi
  done <"$pids"
  rm -f "$pids"
  return "$status"
}

status() {
  "$bin/cloudshape-echo" --status --count "${1:-5}" --timeout 5 "${@:2}" || true
}

cmd="${1:-}"
(($#)) && shift
case "$cmd" in
  start) start "$@" ;;
  stop) stop ;;
  status) status "$@" ;;
  run)
    start "$@"
    trap 'stop; exit 0' INT TERM
    cs_log "running; Ctrl-C stops the services"
    while true; do sleep 1; done ;;
  -h|--help) usage ;;
  *) usage >&2; exit 2 ;;
esac
