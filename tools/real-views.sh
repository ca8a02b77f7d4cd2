#!/usr/bin/env bash
# Single views of the real meshes: each YCB and ravens mesh of ../shared/data/real seen from four
# camera positions with `cloudshape-synth mesh --view`, then `cloudshape-recognize`; counts the
# views whose output is exactly one object of the right shape (docs/performance.md, "Single
# views of the real meshes").
#
#   tools/real-views.sh [--verbose]     (after a build; uses build/bin)
#
# Cameras: (0.5,0.3,0.4) (-0.4,0.2,0.5) (0.1,-0.6,0.3) (0.6,-0.2,0.2) in metres for YCB (about
# 3.5 object sizes away), the same times 100 for the ravens solids (in mm, 20 mm across).
# 20000 points, seed 12. Environment: CLOUDSHAPE_BUILD_DIR (default build), CLOUDSHAPE_REAL_DATA
# (default ../shared/data/real beside the repository).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="$repo/${CLOUDSHAPE_BUILD_DIR:-build}/bin"
real="${CLOUDSHAPE_REAL_DATA:-$repo/../shared/data/real}"
verbose=0
[[ "${1:-}" == --verbose ]] && verbose=1
[[ -x "$bin/cloudshape-synth" && -x "$bin/cloudshape-recognize" ]] ||
  { echo "real-views.sh: build cloudshape-synth and cloudshape-recognize first ($bin)" >&2; exit 2; }
[[ -d "$real/ycb" ]] || { echo "real-views.sh: $real/ycb not found" >&2; exit 2; }

expected_shape() {
  case "$1" in
    *can*) echo cylinder ;;
    *ball*) echo sphere ;;
    *pentagonal_prism*) echo pentagonal_prism ;;
    *plus* | *letter_t* | *star* | *letter_l*) echo prism ;;
    *) echo box ;;
  esac
}

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
views=("0.5,0.3,0.4" "-0.4,0.2,0.5" "0.1,-0.6,0.3" "0.6,-0.2,0.2")
right=0 total=0
for mesh in "$real"/ycb/*.obj "$real"/ycb/*.ply "$real"/ravens/*.obj; do
  [[ -f "$mesh" ]] || continue
  name="$(basename "$mesh")"
  want="$(expected_shape "$name")"
  scale=1
  [[ "$mesh" == */ravens/* ]] && scale=100
  row="" mesh_right=0
  for view in "${views[@]}"; do
    camera="$(awk -v s="$scale" -F, '{printf "%g,%g,%g", $1*s, $2*s, $3*s}' <<<"$view")"
    "$bin/cloudshape-synth" mesh "$mesh" --points 20000 --view "$camera" --seed 12 \
      -o "$work/view.pcd" >/dev/null
    shapes="$("$bin/cloudshape-recognize" "$work/view.pcd" |
      grep -o '"shape": *"[a-z_]*"' | sed 's/.*"\([a-z_]*\)"$/\1/' | paste -sd+ -)"
    total=$((total + 1))
    if [[ "$shapes" == "$want" ]]; then
      right=$((right + 1)) mesh_right=$((mesh_right + 1))
    fi
    row+=" ${shapes:-none}"
  done
  printf '| %s | %s | %d/%d |' "$name" "$want" "$mesh_right" "${#views[@]}"
  ((verbose)) && printf '%s |' "$row"
  printf '\n'
done
echo "right single shape: $right/$total views"
