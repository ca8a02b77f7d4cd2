# Shared by tools/test.sh and tools/demo.sh (source it, don't run it):
# the Debian packages cloudshape needs, installing only what is missing, and the build.
# shellcheck shell=bash

# The Debian 12 packages needed to build cloudshape (docker/Dockerfile installs only these).
CLOUDSHAPE_BUILD_PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config
  libeigen3-dev libnanoflann-dev libyaml-cpp-dev libspdlog-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  liblzf-dev liblz4-dev libzstd-dev zlib1g-dev libtinyobjloader-dev libcli11-dev nlohmann-json3-dev libcairo2-dev
  libfastrtps-dev libfastcdr-dev fastddsgen
)
# The one list tools/test.sh and tools/demo.sh install: the build plus what the default tests
# use (Cyclone DDS for the interop test, docker-compose to validate docker/compose.yaml, gdb
# to kill a service inside a receive in the fault test, shellcheck for the script checks,
# python3-jsonschema to validate the JSON output against tests/report/result.schema.json,
# python3-numpy for tools/lidar_moved_ball.py, whose documented run the docs test makes).
CLOUDSHAPE_DEB_PACKAGES=(
  "${CLOUDSHAPE_BUILD_PACKAGES[@]}"
  cyclonedds-dev cyclonedds-tools
  docker-compose
  openssl tcpdump gdb
  shellcheck python3-jsonschema python3-numpy
)
# Only tools/fuzz.sh needs these: clang and its libFuzzer runtime (libclang_rt.fuzzer).
# shellcheck disable=SC2034  # read by tools/fuzz.sh
CLOUDSHAPE_FUZZ_DEB_PACKAGES=(clang-14 libclang-rt-14-dev)
# Only for the long container test (tests/docker/podman_stack_test.sh installs them itself):
# podman with runc (crun refuses these machines' hybrid cgroups), podman-compose, and
# debootstrap for a base image without a registry.
# shellcheck disable=SC2034  # used by tests/docker/podman_stack_test.sh
CLOUDSHAPE_CONTAINER_PACKAGES=(podman runc podman-compose debootstrap)

CLOUDSHAPE_REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
# build/ per INTERFACE.md; CLOUDSHAPE_BUILD_DIR overrides it (e.g. for a second, private tree).
# shellcheck disable=SC2034  # read by tools/test.sh (--sanitize picks its own tree unless set)
CLOUDSHAPE_BUILD_DIR_SET="${CLOUDSHAPE_BUILD_DIR:+yes}"
CLOUDSHAPE_BUILD_DIR="${CLOUDSHAPE_BUILD_DIR:-$CLOUDSHAPE_REPO/build}"
CLOUDSHAPE_JOBS="${CLOUDSHAPE_JOBS:-$(nproc 2>/dev/null || echo 2)}"
CLOUDSHAPE_LOG_TAG="${CLOUDSHAPE_LOG_TAG:-cloudshape}"

cs_log() { printf '[%s] %s\n' "$CLOUDSHAPE_LOG_TAG" "$*" >&2; }
cs_die() { printf '[%s] ERROR: %s\n' "$CLOUDSHAPE_LOG_TAG" "$*" >&2; exit 1; }

# Prints the packages among the arguments (default: CLOUDSHAPE_DEB_PACKAGES) that are not
# installed, one per line.
cs_missing_packages() {
  local pkg status
  (($#)) || set -- "${CLOUDSHAPE_DEB_PACKAGES[@]}"
  for pkg in "$@"; do
    status="$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)"
    [[ "$status" == "install ok installed" ]] || printf '%s\n' "$pkg"
  done
}

# Installs the missing packages non-interactively; touches apt only when something is missing.
# Arguments: extra packages wanted besides CLOUDSHAPE_DEB_PACKAGES (e.g. the fuzzing ones).
# shellcheck disable=SC2120  # the usual callers want only the default list
cs_ensure_packages() {
  command -v dpkg-query >/dev/null 2>&1 || cs_die "dpkg-query not found: this script expects Debian 12"
  local -a wanted=("${CLOUDSHAPE_DEB_PACKAGES[@]}" "$@")
  local missing
  mapfile -t missing < <(cs_missing_packages "${wanted[@]}")
  if ((${#missing[@]} == 0)); then
    cs_log "dependencies: all ${#wanted[@]} Debian packages present"
    return 0
  fi
  cs_log "dependencies: installing ${missing[*]}"
  local -a sudo_cmd=()
  if [[ "$(id -u)" -ne 0 ]]; then
    command -v sudo >/dev/null 2>&1 || cs_die "not root and no sudo: install ${missing[*]} first"
    sudo_cmd=(sudo -E)
    # Without a terminal (CI) sudo must not wait for a password.
    [[ -t 0 ]] || sudo_cmd+=(-n)
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -q || cs_die "apt-get update failed"
  "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends \
    -o Dpkg::Options::=--force-confdef -o Dpkg::Options::=--force-confold "${missing[@]}" \
    || cs_die "apt-get install failed"
  mapfile -t missing < <(cs_missing_packages "${wanted[@]}")
  ((${#missing[@]} == 0)) || cs_die "still missing after install: ${missing[*]}"
}

# The npm packages of the MCAP interop test (tests/interop/mcap-node), exactly as its
# package-lock.json pins them (npm ci). Node.js and npm come from Debian when the machine has
# neither (a machine with a newer Node.js keeps it). Runs npm only when the lockfile changed.
CLOUDSHAPE_NPM_DIRS=("$CLOUDSHAPE_REPO/tests/interop/mcap-node")
cs_ensure_npm_packages() {
  if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
    cs_ensure_packages nodejs npm
  fi
  local dir stamp want
  for dir in "${CLOUDSHAPE_NPM_DIRS[@]}"; do
    stamp="$dir/node_modules/.cloudshape-lock.sha256"
    want="$(sha256sum "$dir/package-lock.json" | cut -d' ' -f1)"
    if [[ -f "$stamp" && "$(cat "$stamp")" == "$want" ]]; then
      cs_log "npm: ${dir#"$CLOUDSHAPE_REPO"/} up to date"
      continue
    fi
    cs_log "npm: npm ci in ${dir#"$CLOUDSHAPE_REPO"/}"
    (cd "$dir" && npm ci --no-audit --no-fund --loglevel=error) >&2 || cs_die "npm ci failed in $dir"
    printf '%s\n' "$want" >"$stamp"
  done
}

# Configures (Release) and builds into CLOUDSHAPE_BUILD_DIR: every target, or only the targets
# given as arguments. CLOUDSHAPE_CMAKE_ARGS (space-separated) is passed to the configure step,
# e.g. "-DCLOUDSHAPE_SANITIZE=ON".
# shellcheck disable=SC2120  # most callers build every target
cs_configure_and_build() {
  local -a targets=()
  (($#)) && targets=(--target "$@")
  local -a gen=() extra=()
  read -r -a extra <<<"${CLOUDSHAPE_CMAKE_ARGS:-}"
  local cache="$CLOUDSHAPE_BUILD_DIR/CMakeCache.txt"
  # Keep an existing tree's generator (switching generators in place makes cmake fail).
  if [[ ! -f "$cache" ]] && command -v ninja >/dev/null 2>&1; then
    gen=(-G Ninja)
  fi
  mkdir -p "$CLOUDSHAPE_BUILD_DIR"
  # ccache keeps its cache in the build tree when the home directory is not writable (CI).
  if [[ -z "${CCACHE_DIR:-}" && ! -w "${HOME:-/nonexistent}" ]]; then
    export CCACHE_DIR="$CLOUDSHAPE_BUILD_DIR/.ccache"
  fi
  local log="$CLOUDSHAPE_BUILD_DIR/configure.log"
  cs_log "configure: $CLOUDSHAPE_BUILD_DIR (Release)"
  if ! cmake -S "$CLOUDSHAPE_REPO" -B "$CLOUDSHAPE_BUILD_DIR" "${gen[@]}" \
      -DCMAKE_BUILD_TYPE=Release "${extra[@]}" >"$log" 2>&1; then
    cat "$log" >&2
    cs_die "cmake configure failed (log: $log)"
  fi
  cs_log "build: $CLOUDSHAPE_JOBS parallel jobs"
  # Build progress goes to stderr so that stdout carries only results (demo.sh: JSON lines).
  cmake --build "$CLOUDSHAPE_BUILD_DIR" --parallel "$CLOUDSHAPE_JOBS" "${targets[@]}" >&2 || cs_die "build failed"
}
