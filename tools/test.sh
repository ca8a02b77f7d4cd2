#!/usr/bin/env bash
# Installs what is missing, builds build/ (Release) and runs the tests with ctest.
# Exit status 0 only if the build and every selected test pass. Idempotent.
#
#   tools/test.sh            # every test except those labelled "long"
#   tools/test.sh --long     # every test
#   tools/test.sh -R REGEX   # only the tests whose name matches (ctest -R)
#   tools/test.sh --sanitize # ASan + UBSan build in build-sanitize/, the tests not labelled long
#
# Environment: CLOUDSHAPE_BUILD_DIR (default build/, or build-sanitize/ with --sanitize),
# CLOUDSHAPE_JOBS (default: all cores), CLOUDSHAPE_CMAKE_ARGS (extra configure arguments),
# CLOUDSHAPE_TEST_TIMEOUT (seconds per test, default 600).
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=test.sh
# shellcheck source-path=SCRIPTDIR source=lib/deps.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

usage() { sed -n '2,12s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; }

long=0
sanitize=0
ctest_filter=()
while (($#)); do
  case "$1" in
    --long) long=1 ;;
    --sanitize) sanitize=1 ;;
    -R) [[ $# -ge 2 ]] || cs_die "-R needs a regex"; ctest_filter=(-R "$2"); shift ;;
    -h|--help) usage; exit 0 ;;
    *) usage >&2; cs_die "unknown argument: $1" ;;
  esac
  shift
done

if ((sanitize)); then
  ((long == 0)) || cs_die "--sanitize runs the short tests only"
  [[ -n "${CLOUDSHAPE_BUILD_DIR_SET:-}" ]] || CLOUDSHAPE_BUILD_DIR="$CLOUDSHAPE_REPO/build-sanitize"
  CLOUDSHAPE_CMAKE_ARGS="${CLOUDSHAPE_CMAKE_ARGS:-} -DCLOUDSHAPE_SANITIZE=ON"
  # A finding stops the program (the build sets -fno-sanitize-recover) and fails its test.
  # Leaks are not checked: Fast DDS keeps singletons alive until exit by design.
  export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=0:abort_on_error=1}"
  export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
fi

start=$SECONDS
cd "$CLOUDSHAPE_REPO"
cs_ensure_packages
cs_configure_and_build

ctest_args=(--test-dir "$CLOUDSHAPE_BUILD_DIR" --output-on-failure --no-tests=error
            -j "$CLOUDSHAPE_JOBS" --timeout "${CLOUDSHAPE_TEST_TIMEOUT:-600}" "${ctest_filter[@]}")
if ((long)); then
  cs_log "tests: all (ctest ${ctest_args[*]})"
else
  ctest_args+=(-LE long)
  cs_log "tests: all but label 'long' (ctest ${ctest_args[*]}); --long runs everything"
fi
status=0
ctest "${ctest_args[@]}" || status=$?
elapsed=$((SECONDS - start))
if ((status == 0)); then
  cs_log "PASS: build and tests succeeded in ${elapsed}s"
else
  cs_log "FAIL: ctest exit status $status after ${elapsed}s"
fi
exit "$status"
