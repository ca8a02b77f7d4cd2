#!/usr/bin/env bash
# Long container test: builds the cloudshape image with podman from a debootstrapped Debian 12
# base (no registry needed), runs docker/compose.yaml with podman-compose in a network
# namespace of its own, injects the synthetic suite and checks that the echo container prints
# what cloudshape-recognize prints. Skips (exit 77) without root, podman or a network namespace.
#
#   tests/docker/podman_stack_test.sh BIN_DIR COMPARE_EXE DOMAIN [CACHE_DIR]
#
# BIN_DIR holds cloudshape-synth and cloudshape-recognize (host build); COMPARE_EXE is
# dds_compare_results (field by field, axes included); DOMAIN is the test's DDS domain
# (tests/dds/domains.cmake) + CLOUDSHAPE_TEST_DOMAIN_OFFSET inside the containers.
# CACHE_DIR (default BIN_DIR/../podman) keeps podman's storage between
# runs: the base image (debootstrapped again only when the package list or mirror changes) and
# the build layers (rebuilt only when the sources change). Installs podman, runc,
# podman-compose and debootstrap when missing (tools/lib/deps.sh, CLOUDSHAPE_CONTAINER_PACKAGES).
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=podman_stack_test
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck source-path=SCRIPTDIR source=../../tools/lib/deps.sh
source "$here/../../tools/lib/deps.sh"

skip() { cs_log "SKIP: $*"; exit 77; }
(($# >= 3)) || { sed -n '2,16s/^# \{0,1\}//p' "${BASH_SOURCE[0]}" >&2; exit 2; }
bin="$(cd "$1" && pwd)"
compare="$2"
domain="$3"
cache="${4:-$bin/../podman}"
for exe in "$bin/cloudshape-synth" "$bin/cloudshape-recognize" "$compare"; do
  [[ -x "$exe" ]] || cs_die "$exe: not built"
done

[[ "$(id -u)" -eq 0 ]] || skip "needs root (podman, ip netns)"
(cs_ensure_packages "${CLOUDSHAPE_CONTAINER_PACKAGES[@]}") || skip "cannot install ${CLOUDSHAPE_CONTAINER_PACKAGES[*]}"

start=$SECONDS
phase_start=$SECONDS
phase() { cs_log "$1 ($((SECONDS - phase_start)) s)"; phase_start=$SECONDS; }

# podman's settings for these machines (see shared/containers/podman-env.sh): runc with
# cgroupfs (crun refuses hybrid cgroups), explicit ulimits, storage set before the first call.
mkdir -p "$cache"
cache="$(cd "$cache" && pwd)"
cat >"$cache/containers.conf" <<CONF
[containers]
default_ulimits = ["nofile=20000:20000", "nproc=4096:4096"]
[engine]
runtime = "runc"
cgroup_manager = "cgroupfs"
[network]
network_config_dir = "$cache/networks"
CONF
cat >"$cache/storage.conf" <<CONF
[storage]
driver = "overlay"
graphroot = "$cache/store"
runroot = "$cache/run"
CONF
export CONTAINERS_CONF="$cache/containers.conf" CONTAINERS_STORAGE_CONF="$cache/storage.conf"

ns="cloudshape-podman-$$"
project="csp$$"
compose_file="$CLOUDSHAPE_REPO/docker/compose.yaml"
work="$(mktemp -d)"
in_ns() { nsenter --net="/run/netns/$ns" "$@"; }
ns_made=0
# shellcheck disable=SC2317  # called by the EXIT trap
cleanup() {
  local status=$?
  if ((ns_made)); then
    local c
    for c in $(in_ns podman ps -a -q --filter "label=io.podman.compose.project=$project" 2>/dev/null); do
      if ((status != 0 && status != 77)); then
        cs_log "log of $(in_ns podman inspect -f '{{.Name}}' "$c" 2>/dev/null):"
        in_ns podman logs "$c" 2>&1 | tail -n 30 >&2 || true
      fi
      in_ns podman rm -f -t 5 "$c" >/dev/null 2>&1 || true
    done
    in_ns podman network rm -f "${project}_default" >/dev/null 2>&1 || true
    ip netns del "$ns" 2>/dev/null || true
  fi
  # Build layers of earlier sources are no longer needed; the base and the latest image stay.
  podman image prune -f >/dev/null 2>&1 || true
  rm -rf "$work"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

ip netns add "$ns" 2>/dev/null || skip "ip netns add refused"
ns_made=1
ip -n "$ns" link set lo up

# The base: debootstrap minbase with every build package, so the image builds offline.
mirror="$(sed -n 's/^URIs:[[:space:]]*\([^[:space:]]*\).*/\1/p' /etc/apt/sources.list.d/debian.sources 2>/dev/null | head -n 1)"
mirror="${mirror:-http://deb.debian.org/debian}"
include="$(IFS=,; echo "${CLOUDSHAPE_BUILD_PACKAGES[*]}")"
base_key="$(printf '%s\n' bookworm "$mirror" "$include" | sha256sum | cut -c1-12)"
base="localhost/cloudshape-base:$base_key"
if podman image exists "$base"; then
  cs_log "base image $base cached"
else
  rootfs="$cache/rootfs"
  rm -rf "$rootfs"
  cs_log "debootstrap bookworm from $mirror (log: $cache/debootstrap.log)"
  debootstrap --variant=minbase --include="$include" bookworm "$rootfs" "$mirror" \
    >"$cache/debootstrap.log" 2>&1 || { tail -n 20 "$cache/debootstrap.log" >&2; cs_die "debootstrap failed"; }
  tar -C "$rootfs" -c . | podman import - "$base" >/dev/null
  rm -rf "$rootfs"
  phase "base image $base imported"
fi

# The image, built with no network at all: everything comes from the base. The build stage
# gets a tag of its own, else the prune at exit deletes it (untagged) and with it the cache of
# the compile step.
cs_log "podman build (log: $cache/build.log)"
build_args=(--network none -f "$CLOUDSHAPE_REPO/docker/Dockerfile" --build-arg "BASE=$base"
            --build-arg "JOBS=$CLOUDSHAPE_JOBS")
{ in_ns podman build "${build_args[@]}" --target build -t localhost/cloudshape-build:latest "$CLOUDSHAPE_REPO" &&
  in_ns podman build "${build_args[@]}" -t localhost/cloudshape:latest "$CLOUDSHAPE_REPO"; } \
  >"$cache/build.log" 2>&1 || { tail -n 30 "$cache/build.log" >&2; cs_die "podman build failed"; }
phase "image localhost/cloudshape:latest built"

# The clouds and what the recognizer says about them on the host.
"$bin/cloudshape-synth" suite --out "$work/samples" --points 20000 --seed 11 --count 1 >/dev/null
find "$work/samples" -type f ! -name '*.pcd' -delete
mapfile -t clouds < <(find "$work/samples" -name '*.pcd' | sort)
((${#clouds[@]} > 0)) || cs_die "cloudshape-synth wrote no cloud"
"$bin/cloudshape-recognize" "${clouds[@]}" >"$work/expected.jsonl"

export BASE="$base" CLOUDSHAPE_SAMPLES="$work/samples"
export CLOUDSHAPE_DOMAIN=$((domain + ${CLOUDSHAPE_TEST_DOMAIN_OFFSET:-0}))
compose() { in_ns podman-compose -p "$project" -f "$compose_file" "$@"; }
compose up -d >"$work/up.log" 2>&1 || { cat "$work/up.log" >&2; cs_die "podman-compose up failed"; }
# podman-compose 1.0.3 ignores compose profiles and starts inject with the rest; docker-compose
# and newer podman-compose leave it to an explicit run.
if in_ns podman container exists "${project}_inject_1"; then
  inject_status="$(in_ns podman wait "${project}_inject_1")"
else
  inject_status=0
  compose run --rm inject >"$work/inject.log" 2>&1 || inject_status=$?
fi
[[ "$inject_status" == 0 ]] || cs_die "inject exited with $inject_status"
phase "stack up, ${#clouds[@]} clouds injected"

results() { in_ns podman logs "${project}_echo_1" 2>/dev/null | grep '^{' || true; }
deadline=$((SECONDS + 300))
while (($(results | wc -l) < ${#clouds[@]})); do
  ((SECONDS < deadline)) || cs_die "echo printed $(results | wc -l) of ${#clouds[@]} results in 300 s"
  sleep 1
done
results >"$work/actual.jsonl"
phase "echo printed ${#clouds[@]} results"
"$compare" "$work/expected.jsonl" "$work/actual.jsonl" >&2 || cs_die "the containers' results differ from cloudshape-recognize's"

# Every service stops cleanly on SIGTERM (podman stop), exit status 0.
for service in ingest planes keypoints classifier solver echo; do
  in_ns podman stop -t 30 "${project}_${service}_1" >/dev/null
  code="$(in_ns podman inspect -f '{{.State.ExitCode}}' "${project}_${service}_1")"
  [[ "$code" == 0 ]] || cs_die "$service exited with $code on SIGTERM"
done
compose down >/dev/null 2>&1 || true
cs_log "PASS: ${#clouds[@]} clouds through the podman-compose stack, same results as cloudshape-recognize, every service stopped cleanly ($((SECONDS - start)) s)"
