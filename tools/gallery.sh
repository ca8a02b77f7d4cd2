#!/usr/bin/env bash
# Remakes the gallery of docs/pictures.md: docs/images/*.png, drawn by `cloudshape-recognize
# --render` from the real sample data of ../shared/data/real.
#
#   tools/gallery.sh      (installs what is missing, builds the two tools it needs)
#
# Pictures: single views of three YCB scans (a box, a can, a ball) and of the ravens pentagonal
# prism, made with `cloudshape-synth mesh --view` (20000 points, seed 12, the first camera of
# tools/real-views.sh: (0.5,0.3,0.4) m, and the same times 100 for the prism in mm; 0.5 mm noise
# on the YCB views); three mOSD Kinect scenes and PCL's milk carton as they are; the SphereCalib
# lidar scan as it is. Each PNG is reduced to a palette with pngquant to stay under 150 KB.
# Environment: CLOUDSHAPE_BUILD_DIR, CLOUDSHAPE_JOBS, CLOUDSHAPE_REAL_DATA (default
# ../shared/data/real beside the repository).
set -euo pipefail
# shellcheck disable=SC2034  # read by lib/deps.sh
CLOUDSHAPE_LOG_TAG=gallery.sh
# shellcheck source-path=SCRIPTDIR source=lib/deps.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

case "${1:-}" in
  "") ;;
  -h|--help) sed -n '2,13s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; exit 0 ;;
  *) cs_die "unknown argument: $1 (see --help)" ;;
esac

MAX_BYTES=150000
real="${CLOUDSHAPE_REAL_DATA:-$CLOUDSHAPE_REPO/../shared/data/real}"
out="$CLOUDSHAPE_REPO/docs/images"
[[ -d "$real/ycb" ]] || cs_die "no real sample data at $real"

cd "$CLOUDSHAPE_REPO"
cs_ensure_packages pngquant
cs_configure_and_build cloudshape-synth cloudshape-recognize
bin="$CLOUDSHAPE_BUILD_DIR/bin"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
clouds=()
single_view() {  # MESH CAMERA NOISE NAME: a single view of a mesh as a sensor there would see it
  local cloud="$work/$4.pcd"
  "$bin/cloudshape-synth" mesh "$1" --points 20000 --view "$2" --noise "$3" --seed 12 -o "$cloud" >/dev/null \
    || cs_die "cloudshape-synth mesh failed on $1"
  clouds+=("$cloud")
}
for mesh in 003_cracker_box 005_tomato_soup_can 055_baseball; do
  single_view "$real/ycb/${mesh}_google16k.obj" 0.5,0.3,0.4 0.0005 "ycb_${mesh}_view"
done
single_view "$real/ravens/kitting_07_pentagonal_prism.obj" 50,30,40 0 ravens_pentagonal_prism_view
clouds+=("$real/mosd_learn/learn33.pcd" "$real/mosd_learn/learn20.pcd" "$real/pcl/mOSD_learn0_boxes.pcd"
         "$real/pcl/milk.pcd"
         "$real/spherecalib/example3_L1_S1_lidar_sphere.xyz")

cs_log "rendering ${#clouds[@]} clouds"
"$bin/cloudshape-recognize" --render "$work/pictures" "${clouds[@]}" >"$work/results.jsonl" \
  || cs_die "cloudshape-recognize failed"
mkdir -p "$out"
for picture in "$work"/pictures/*.png; do
  target="$out/$(basename "$picture")"
  pngquant --quality 50-95 --speed 1 --strip --force --output "$target" -- "$picture" \
    || cs_die "pngquant failed on $picture"
  bytes="$(stat -c %s "$target")"
  ((bytes <= MAX_BYTES)) || cs_die "$target is $bytes bytes, over $MAX_BYTES"
  cs_log "$target ($((bytes / 1024)) KB)"
done
