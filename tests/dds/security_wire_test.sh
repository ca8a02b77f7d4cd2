#!/usr/bin/env bash
# DDS Security on the wire: one cloud through the five services over UDP on loopback (the
# default localhost profile), captured with tcpdump, plain and then secured.
# Plain, the capture holds the cloud's source name and the type name; secured, neither (the
# payload and discovery are encrypted). Topic names may appear secured only inside the signed
# permissions documents that the authentication handshake exchanges in clear by design.
#
#   tests/dds/security_wire_test.sh BIN_DIR SOURCE_DIR DOMAIN   (+ CLOUDSHAPE_TEST_DOMAIN_OFFSET)
#
# Exit 0 pass, 1 fail, 77 skipped (not root or no tcpdump: capturing needs both).
set -euo pipefail
bin="$1" src="$2" domain=$(($3 + ${CLOUDSHAPE_TEST_DOMAIN_OFFSET:-0}))
command -v tcpdump >/dev/null 2>&1 || { echo "skip: no tcpdump"; exit 77; }
[[ "$(id -u)" -eq 0 ]] || { echo "skip: capturing needs root"; exit 77; }

work="$(mktemp -d)"
pids=()
# shellcheck disable=SC2317  # called by the EXIT trap
cleanup() {
  local p
  for p in "${pids[@]}"; do kill -KILL "$p" 2>/dev/null || true; done
  rm -rf "$work"
}
trap cleanup EXIT

# The default profile carries the data over UDP on loopback, where tcpdump sees it.
export CLOUDSHAPE_DDS_PROFILE=cloudshape_localhost
"$src/tools/make-certs.sh" "$work/pki" 2>/dev/null
marker=ZqxWireMarker
"$bin/cloudshape-synth" shape --shape box --dims 30,20,10 --points 2000 --seed 5 -o "$work/$marker.pcd" >/dev/null
# Fast DDS default port mapping: every port of a domain lies in 7400 + 250 * domain + 0..249.
port_lo=$((7400 + 250 * domain))

# Runs the pipeline once (security folder $1, empty: plain) under tcpdump; capture in $2.
run_once() {
  local security="$1" capture="$2" p tcpdump_pid echo_pid
  pids=()
  tcpdump -i lo -U -w "$capture" "udp portrange $port_lo-$((port_lo + 249))" 2>"$capture.log" &
  tcpdump_pid=$!
  pids+=("$tcpdump_pid")
  # Nothing starts before tcpdump captures: a late capture would make the secured run pass empty.
  local deadline=$((SECONDS + 60))
  until grep -q "listening on" "$capture.log"; do
    ((SECONDS < deadline)) || { echo "FAIL: tcpdump did not start capturing in 60 s"; exit 1; }
    kill -0 "$tcpdump_pid" 2>/dev/null || { echo "FAIL: tcpdump exited: $(cat "$capture.log")"; exit 1; }
    sleep 0.1
  done
  "$bin/cloudshape-echo" --domain "$domain" --security "$security" --count 1 --timeout 60 >"$capture.echo" 2>&1 &
  echo_pid=$!
  pids+=("$echo_pid")
  local -a services=()
  for p in ingest planes keypoints classifier solver; do
    "$bin/cloudshape-$p" --domain "$domain" --security "$security" >"$capture.$p.log" 2>&1 &
    services+=("$!")
    pids+=("$!")
  done
  "$bin/cloudshape-inject" --domain "$domain" --security "$security" --wait 60 "$work/$marker.pcd" 2>/dev/null
  wait "$echo_pid"
  for p in "${services[@]}"; do kill -TERM "$p"; done
  for p in "${services[@]}"; do wait "$p"; done
  kill -INT "$tcpdump_pid"
  wait "$tcpdump_pid" || true
  grep -q "$marker" "$capture.echo" || { echo "FAIL: no result for the cloud"; exit 1; }
}

count() { grep -a -c "$1" "$2" || true; }

run_once "" "$work/plain.pcap"
run_once "$work/pki" "$work/secured.pcap"
status=0
# Both captures hold the run's RTPS messages (their header stays in clear when secured): the
# secured one is not clean for being empty.
for run in plain secured; do
  rtps="$(count RTPS "$work/$run.pcap")"
  printf 'RTPS in the %s capture: %s lines\n' "$run" "$rtps"
  ((rtps > 0)) || { echo "FAIL: the $run capture holds no RTPS message"; status=1; }
done
for needle in "$marker" RawCloud ShapeResult; do
  plain="$(count "$needle" "$work/plain.pcap")"
  secured="$(count "$needle" "$work/secured.pcap")"
  printf '%-14s plain %3s  secured %3s\n' "$needle" "$plain" "$secured"
  # The plain run is the control: it shows that the capture sees the traffic at all.
  ((plain > 0)) || { echo "FAIL: '$needle' not in the plain capture"; status=1; }
  ((secured == 0)) || { echo "FAIL: '$needle' in clear in the secured capture"; status=1; }
done
# Topic names outside a permissions document are discovery data in clear (plain: yes).
outside() { grep -a -o '.\{0,8\}cloudshape_raw_cloud' "$1" | grep -c -v '<topic>' || true; }
plain="$(outside "$work/plain.pcap")"
secured="$(outside "$work/secured.pcap")"
printf 'cloudshape_raw_cloud outside permissions documents: plain %s  secured %s\n' "$plain" "$secured"
((plain > 0)) || { echo "FAIL: no topic name in the plain discovery traffic"; status=1; }
((secured == 0)) || { echo "FAIL: a topic name in clear outside the permissions"; status=1; }
exit "$status"
