#!/usr/bin/env bash
# cloudshape against PCL and Open3D, side by side, in one run (issue 13). Prints a Markdown
# table; writes it, a JSON with every sample, the samples and the raw outputs to --out.
#
#   tools/bench_peers.sh [--reps 5] [--points 100000] [--shapes "box cylinder cone sphere"]
#                        [--scenes DIR | --no-scenes] [--out DIR] [--no-install]
#
# Installs what is missing from Debian (the build's packages, libpcl-dev, python3-open3d),
# builds cloudshape and the peer programs (tools/peers: a CMake project of its own, so PCL
# never becomes a dependency of the default build), draws one noisy cloud per shape
# (cloudshape-synth, fixed seeds, random pose, noise 0.5% of the size), then --reps times, in
# turn and in a rotating order: cloudshape-recognize (its own timings_ms.total), pcl-shapes
# (voxel grid, normals, planes, SAC fit of the shape) and open3d_shapes.py (voxel grid,
# normals, planes: Open3D has no cylinder, cone or sphere fit). Scene row: every frame of DIR
# (default ../shared/data/real/mosd_learn) through cloudshape-bench --scenes (whole
# recognition, per frame) and pcl-lccp (table plane removed, SupervoxelClustering +
# LCCPSegmentation with PCL's example parameters), alternating, --reps times.
# Every time is measured inside its program around the pipeline, not process start or file
# reading. Medians per shape and per frame; ratio = cloudshape / fastest peer (below 1:
# cloudshape is faster). The load average before and after goes into the table: the machine is
# shared. docs/peers.md shows the figures and how to read them.
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=bench_peers.sh
# shellcheck source-path=SCRIPTDIR source=lib/deps.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

reps=5
points=100000
shapes="box cylinder cone sphere"
scenes="$CLOUDSHAPE_REPO/../shared/data/real/mosd_learn"
out="$CLOUDSHAPE_BUILD_DIR/peers-bench"
install=1
while (($#)); do
  case "$1" in
    --reps) reps="$2"; shift ;;
    --points) points="$2"; shift ;;
    --shapes) shapes="$2"; shift ;;
    --scenes) scenes="$2"; shift ;;
    --no-scenes) scenes="" ;;
    --out) out="$2"; shift ;;
    --no-install) install=0 ;;
    -h|--help) sed -n '2,24s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) cs_die "unknown argument: $1" ;;
  esac
  shift
done
[[ "$reps" =~ ^[1-9][0-9]*$ ]] || cs_die "--reps wants a positive whole number, not '$reps'"
if [[ -n "$scenes" && ! -d "$scenes" ]]; then
  cs_die "no scene folder $scenes (check out shared/ beside the repository, or --no-scenes)"
fi

# Debian's python3-open3d is importable only by Debian's own python, not a pyenv or venv one.
py=/usr/bin/python3
report="$CLOUDSHAPE_REPO/tools/peers/peers_report.py"
if ((install)); then cs_ensure_packages libpcl-dev python3-open3d; fi
# Before the builds, so that a missing Open3D costs no build time.
"$py" -c 'import open3d' 2>/dev/null || cs_die "$py cannot import open3d: install python3-open3d"
cs_configure_and_build cloudshape-recognize cloudshape-synth cloudshape-bench
bin="$CLOUDSHAPE_BUILD_DIR/bin"

peer_build="$CLOUDSHAPE_BUILD_DIR/peers"
peer_gen=()
if [[ ! -f "$peer_build/CMakeCache.txt" ]] && command -v ninja >/dev/null 2>&1; then
  peer_gen=(-G Ninja)
fi
cs_log "build: the PCL peer programs into $peer_build"
cmake -S "$CLOUDSHAPE_REPO/tools/peers" -B "$peer_build" "${peer_gen[@]}" \
  -DCMAKE_BUILD_TYPE=Release >"$CLOUDSHAPE_BUILD_DIR/peers-configure.log" 2>&1 \
  || { cat "$CLOUDSHAPE_BUILD_DIR/peers-configure.log" >&2; cs_die "configuring tools/peers failed"; }
cmake --build "$peer_build" --parallel "$CLOUDSHAPE_JOBS" >&2 || cs_die "building tools/peers failed"

mkdir -p "$out/clouds" "$out/raw"
rm -f "$out"/raw/*  # each run's outputs alone (run_tool appends)
samples="$out/samples.tsv"
: >"$samples"

# One solid per shape, the same files for every tool. Sizes as in the README's examples.
declare -A dims=([box]="30,20,10" [cylinder]="10,30" [cone]="10,30" [sphere]="15"
                 [tetrahedron]="30" [pentagonal_prism]="12,25")
declare -A seeds=([box]=11 [cylinder]=12 [cone]=13 [sphere]=14 [tetrahedron]=15 [pentagonal_prism]=16)
read -r -a shape_list <<<"$shapes"
for shape in "${shape_list[@]}"; do
  [[ -n "${dims[$shape]:-}" ]] || cs_die "unknown shape: $shape"
  "$bin/cloudshape-synth" shape --shape "$shape" --dims "${dims[$shape]}" --points "$points" \
    --seed "${seeds[$shape]}" --random-pose --noise 0.005 -o "$out/clouds/$shape.pcd" >/dev/null
done

# run_tool TOOL SHAPE: one timed run, its output kept and its sample appended.
run_tool() {
  local tool="$1" shape="$2" cloud="$out/clouds/$2.pcd" raw="$out/raw/$1-$2.jsonl"
  case "$tool" in
    cloudshape) "$bin/cloudshape-recognize" "$cloud" ;;
    pcl) "$peer_build/pcl-shapes" --shape "$shape" "$cloud" 2>/dev/null ;;
    open3d) "$py" "$CLOUDSHAPE_REPO/tools/peers/open3d_shapes.py" --shape "$shape" "$cloud" ;;
  esac | tee -a "$raw" | "$py" "$report" record shape "$tool" "$shape" >>"$samples" \
    || cs_die "$tool on $shape gave no result (output: $raw)"
}
# run_scenes TOOL: every frame once, in one process.
run_scenes() {
  local raw="$out/raw/scenes-$1.json"
  case "$1" in
    cloudshape) "$bin/cloudshape-bench" --scenes "$scenes" --json 2>/dev/null >"$raw" ;;
    pcl_lccp) "$peer_build/pcl-lccp" "$scenes"/*.pcd 2>/dev/null >"$raw" ;;
  esac || cs_die "$1 failed on the scenes (output: $raw)"
  "$py" "$report" record scene "$1" <"$raw" >>"$samples" || cs_die "$1: no scene results in $raw"
}

load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
started="$(date -u +%Y-%m-%dT%H:%MZ)"
tools=(cloudshape pcl open3d)
for ((rep = 0; rep < reps; rep++)); do
  cs_log "shapes: repetition $((rep + 1)) of $reps"
  for shape in "${shape_list[@]}"; do
    # A rotating order, so that no tool always runs first (or right after a heavy one).
    for ((k = 0; k < ${#tools[@]}; k++)); do
      run_tool "${tools[(rep + k) % ${#tools[@]}]}" "$shape"
    done
  done
done
if [[ -n "$scenes" ]]; then
  for ((rep = 0; rep < reps; rep++)); do
    cs_log "scenes: repetition $((rep + 1)) of $reps"
    if ((rep % 2)); then run_scenes pcl_lccp; run_scenes cloudshape
    else run_scenes cloudshape; run_scenes pcl_lccp; fi
  done
fi
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"

version() { dpkg-query -W -f='${Version}' "$1" 2>/dev/null | sed 's/[+~].*//'; }
"$py" "$report" report "$samples" --json "$out/peers.json" \
  --meta "pcl=$(version libpcl-dev)" --meta "open3d=$(version python3-open3d)" \
  --meta "points=$points" --meta "repetitions=$reps" --meta "scenes=$(basename "${scenes:-none}")" \
  --meta "cloudshape commit=$(git -C "$CLOUDSHAPE_REPO" rev-parse --short HEAD 2>/dev/null || echo unknown)" \
  --meta "started=$started" --meta "cores=$(nproc)" \
  --meta "load average (1, 5, 15 min) before=$load_before" \
  --meta "load average after=$load_after" | tee "$out/peers.md"
cs_log "wrote $out/peers.md, $out/peers.json and the samples ($samples)"
