#!/usr/bin/env bash
# Runs one libFuzzer target for a while: builds build-fuzz/ (clang, CLOUDSHAPE_FUZZ=ON) if needed.
#
#   tools/fuzz.sh TARGET SECONDS     # TARGET: pcd, ply, xyz, mcap, ingest or pointcloud2
#
# Seeds: tests/fuzz/corpus/TARGET (kept in git); what the fuzzer learns goes to
# build-fuzz/corpus/TARGET; a crash, timeout or leak lands in build-fuzz/artifacts/TARGET/:
# copy it to tests/fuzz/regressions/TARGET/ so the default ctest replays it for ever.
# Environment: CLOUDSHAPE_FUZZ_BUILD_DIR (default build-fuzz/), CLOUDSHAPE_JOBS (build jobs),
# CLOUDSHAPE_FUZZ_ARGS (extra libFuzzer flags, e.g. -jobs=2).
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=fuzz.sh
# shellcheck source-path=SCRIPTDIR source=lib/deps.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

usage() { sed -n '2,10s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; }

[[ $# -eq 2 ]] || { usage >&2; exit 2; }
target="$1"
seconds="$2"
case "$target" in
  pcd|ply|xyz|mcap|ingest|pointcloud2) ;;
  *) usage >&2; cs_die "unknown target '$target' (pcd, ply, xyz, mcap, ingest or pointcloud2)" ;;
esac
[[ "$seconds" =~ ^[0-9]+$ ]] || cs_die "SECONDS must be a whole number, not '$seconds'"

build="${CLOUDSHAPE_FUZZ_BUILD_DIR:-$CLOUDSHAPE_REPO/build-fuzz}"
cs_ensure_packages "${CLOUDSHAPE_FUZZ_DEB_PACKAGES[@]}"
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cs_log "configure: $build (clang, libFuzzer, ASan, UBSan)"
  CC=clang CXX=clang++ cmake -S "$CLOUDSHAPE_REPO" -B "$build" -G Ninja \
    -DCMAKE_BUILD_TYPE=Release -DCLOUDSHAPE_FUZZ=ON >"$build.configure.log" 2>&1 \
    || { cat "$build.configure.log" >&2; cs_die "configure failed"; }
fi
cs_log "build: fuzz_$target"
cmake --build "$build" --target "fuzz_$target" --parallel "$CLOUDSHAPE_JOBS" >&2 || cs_die "build failed"

seeds="$CLOUDSHAPE_REPO/tests/fuzz/corpus/$target"
corpus="$build/corpus/$target"
artifacts="$build/artifacts/$target"
mkdir -p "$corpus" "$artifacts"
args=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
      -artifact_prefix="$artifacts/")
dict="$CLOUDSHAPE_REPO/tests/fuzz/$target.dict"
[[ -f "$dict" ]] && args+=(-dict="$dict")
read -r -a extra <<<"${CLOUDSHAPE_FUZZ_ARGS:-}"
cs_log "run: fuzz_$target for ${seconds}s (corpus $corpus, seeds $seeds, findings $artifacts/)"
status=0
"$build/bin/fuzz_$target" "${args[@]}" "${extra[@]}" "$corpus" "$seeds" || status=$?
if ((status != 0)); then
  cs_log "FINDING: fuzz_$target stopped with status $status; inputs in $artifacts/:"
  ls -1 "$artifacts" >&2
  cs_log "reproduce: $build/bin/fuzz_$target FILE; keep it: cp FILE tests/fuzz/regressions/$target/"
fi
exit "$status"
