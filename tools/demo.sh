#!/usr/bin/env bash
# Installs what is missing, builds build/ (Release), makes the sample clouds and runs the whole
# recognition pipeline on them, in-process and then over DDS. It ends by printing what was found
# as a table, one line per object (cloudshape-recognize --format table); the JSON results are
# kept in build/demo/recognize.jsonl and build/demo/dds.jsonl (progress on stderr).
#
#   tools/demo.sh [--secure]
#
# Samples (in build/samples/, regenerated deterministically on every run):
#   synthetic/  one cloud per shape from cloudshape-synth suite (fixed seed)
#   real/       the real meshes of ../shared/data/real (ycb *.obj *.ply, ravens *.obj) sampled
#               at 20000 points with cloudshape-synth mesh
# plus, read as they are, ../shared/data/real/pcl/*.pcd and spherecalib/*.xyz.
# Environment: CLOUDSHAPE_BUILD_DIR, CLOUDSHAPE_JOBS, CLOUDSHAPE_REAL_DATA (default
# ../shared/data/real beside the repository).
# Then the same clouds through the DDS pipeline: tools/launch.sh starts the five services
# (logs in build/logs/), cloudshape-echo writes one JSON line per cloud (the same objects as
# the recognizer's), cloudshape-inject publishes the clouds, and the services are stopped.
# CLOUDSHAPE_DOMAIN picks the DDS domain (default 0); traffic stays on this host.
# --secure: the DDS part with DDS Security (tools/make-certs.sh makes the test PKI in
# build/pki, every participant authenticates and encrypts; docs/dds.md "DDS Security").
# Exit status: 0 when every cloud was read and every DDS result arrived.
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=demo.sh
# shellcheck source-path=SCRIPTDIR source=lib/deps.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

secure=0
case "${1:-}" in
  "") ;;
  --secure) secure=1 ;;
  -h|--help) sed -n '2,22s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; exit 0 ;;
  *) cs_die "unknown argument: $1 (see --help)" ;;
esac

SEED=7
SYNTH_POINTS=20000
REAL_POINTS=20000
real_data="${CLOUDSHAPE_REAL_DATA:-$CLOUDSHAPE_REPO/../shared/data/real}"

cd "$CLOUDSHAPE_REPO"
cs_ensure_packages
cs_configure_and_build

bin="$CLOUDSHAPE_BUILD_DIR/bin"
for tool in cloudshape-synth cloudshape-recognize; do
  [[ -x "$bin/$tool" ]] || cs_die "$bin/$tool was not built"
done
samples="$CLOUDSHAPE_BUILD_DIR/samples"
results="$CLOUDSHAPE_BUILD_DIR/demo"
mkdir -p "$samples" "$results"

clouds=()
add_clouds() {  # appends the cloud files (.pcd .ply .xyz .txt) found in a folder, sorted
  local f
  while IFS= read -r -d '' f; do clouds+=("$f"); done < <(
    find "$1" -maxdepth 1 -type f \( -name '*.pcd' -o -name '*.ply' -o -name '*.xyz' \
      -o -name '*.txt' \) -print0 | sort -z)
}

cs_log "samples: one synthetic cloud per shape ($SYNTH_POINTS points, seed $SEED)"
rm -rf "$samples/synthetic"
"$bin/cloudshape-synth" suite --out "$samples/synthetic" --points "$SYNTH_POINTS" --seed "$SEED" \
  --count 1 >/dev/null
add_clouds "$samples/synthetic"

if [[ -d "$real_data" ]]; then
  cs_log "samples: real meshes from $real_data ($REAL_POINTS points each)"
  mkdir -p "$samples/real"
  shopt -s nullglob
  for mesh in "$real_data"/ycb/*.obj "$real_data"/ycb/*.ply "$real_data"/ravens/*.obj; do
    name="$(basename "${mesh%.*}")"
    out="$samples/real/$name.pcd"
    if [[ ! -s "$out" || "$mesh" -nt "$out" || "$bin/cloudshape-synth" -nt "$out" ]]; then
      "$bin/cloudshape-synth" mesh "$mesh" --points "$REAL_POINTS" --seed "$SEED" -o "$out" \
        >/dev/null || cs_die "cloudshape-synth mesh failed on $mesh"
    fi
    clouds+=("$out")
  done
  real_clouds=("$real_data"/pcl/*.pcd "$real_data"/spherecalib/*.xyz)
  shopt -u nullglob
  clouds+=("${real_clouds[@]}")
else
  cs_log "samples: no real data at $real_data (skipped)"
fi

((${#clouds[@]} > 0)) || cs_die "no sample clouds were made"
cs_log "recognize (in-process): ${#clouds[@]} clouds, one JSON line each in $results/recognize.jsonl"
status=0
cs_log "pictures: $CLOUDSHAPE_BUILD_DIR/pictures (one PNG per cloud, docs/pictures.md)"
"$bin/cloudshape-recognize" --render "$CLOUDSHAPE_BUILD_DIR/pictures" "${clouds[@]}" >"$results/recognize.jsonl" || status=$?
if ((status == 0)); then
  cs_log "done: ${#clouds[@]} clouds recognised"
else
  cs_log "cloudshape-recognize exited with status $status"
fi

# The DDS pipeline on the same clouds.
domain="${CLOUDSHAPE_DOMAIN:-0}"
launch="$CLOUDSHAPE_REPO/tools/launch.sh"
export CLOUDSHAPE_BUILD_DIR
"$launch" stop >/dev/null 2>&1 || true  # leftovers of an interrupted run
if ((secure)); then
  "$CLOUDSHAPE_REPO/tools/make-certs.sh" "$CLOUDSHAPE_BUILD_DIR/pki"
  export CLOUDSHAPE_SECURITY_DIR="$CLOUDSHAPE_BUILD_DIR/pki"  # read by launch.sh, echo and inject
  cs_log "dds: DDS Security on (PKI $CLOUDSHAPE_SECURITY_DIR)"
fi
cs_log "dds: starting the five services on domain $domain (logs: $CLOUDSHAPE_BUILD_DIR/logs)"
"$launch" start --domain "$domain"
echo_pid=""
# shellcheck disable=SC2317  # called by the EXIT trap
stop_all() {
  [[ -z "$echo_pid" ]] || kill -TERM "$echo_pid" 2>/dev/null || true
  "$launch" stop >/dev/null || true
}
trap stop_all EXIT
"$bin/cloudshape-echo" --domain "$domain" --count "${#clouds[@]}" --timeout 600 >"$results/dds.jsonl" &
echo_pid=$!
cs_log "dds: injecting ${#clouds[@]} clouds; cloudshape-echo writes one JSON line each to $results/dds.jsonl"
"$bin/cloudshape-inject" --domain "$domain" --wait 120 "${clouds[@]}" 2>"$CLOUDSHAPE_BUILD_DIR/logs/inject.log" \
  || { cs_log "cloudshape-inject failed (log: $CLOUDSHAPE_BUILD_DIR/logs/inject.log)"; status=1; }
if wait "$echo_pid"; then
  cs_log "dds: ${#clouds[@]} results received"
else
  cs_log "dds: cloudshape-echo did not receive every result"
  status=1
fi
echo_pid=""
"$launch" stop
trap - EXIT

# What a person wants to see last: the objects, one line each. The recognizer runs once more for
# it (a second or two for the samples) so that the JSON above stays untouched for scripts.
cs_log "results (JSON: $results/recognize.jsonl, $results/dds.jsonl; pictures: $CLOUDSHAPE_BUILD_DIR/pictures):"
"$bin/cloudshape-recognize" --format table "${clouds[@]}" || true
exit "$status"
