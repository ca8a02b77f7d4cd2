#!/usr/bin/python3
"""open3d_shapes.py --shape box|cylinder|cone|sphere FILE.pcd

The Open3D pipeline of tools/bench_peers.sh for one solid: the same steps as pcl-shapes up
to its fit, with Open3D's own calls. Voxel grid at cloudshape's point budget (edge from the
bounding-box diagonal / 200, grown until at most 12 000 points remain: voxel_budget.hpp),
normals (16 nearest neighbours; Open3D runs them on all cores), RANSAC planes peeled while
each holds at least 6% of the cloud, at most the shape's faces or caps (plane_peel.hpp).
Open3D 0.16 has no cylinder, cone or sphere fit, so for those it stops after the planes.
Prints one JSON line; "ms" is the pipeline alone, the import and the file read excluded.
Debian's python3-open3d installs into /usr/bin/python3's path (not a pyenv or venv python).
"""
import json
import math
import os
import sys
import time

import open3d as o3d

DIVISIONS = 200.0
MAX_POINTS = 12000
MIN_SHARE = 0.06
MAX_PLANES = {"box": 6, "cylinder": 2, "cone": 1, "sphere": 1}


def downsample_to_budget(cloud):
    diagonal = float(math.dist(cloud.get_min_bound(), cloud.get_max_bound()))
    leaf = diagonal / DIVISIONS
    down = cloud.voxel_down_sample(leaf)
    for _ in range(4):  # a surface's voxel count falls with the square of the edge
        if len(down.points) <= MAX_POINTS:
            break
        leaf *= 1.02 * math.sqrt(len(down.points) / MAX_POINTS)
        down = cloud.voxel_down_sample(leaf)
    return down, leaf


def peel_planes(cloud, threshold, max_planes):
    floor = int(MIN_SHARE * len(cloud.points))
    planes = 0
    while planes < max_planes and len(cloud.points) >= max(floor, 3):
        _, inliers = cloud.segment_plane(threshold, 3, 1000)
        if len(inliers) < floor or not inliers:
            break
        planes += 1
        cloud = cloud.select_by_index(inliers, invert=True)
    return cloud, planes


def main(argv):
    if len(argv) != 4 or argv[1] != "--shape" or argv[2] not in MAX_PLANES:
        print(__doc__.splitlines()[0], file=sys.stderr)
        return 2
    shape, path = argv[2], argv[3]
    cloud = o3d.io.read_point_cloud(path)
    if not cloud.has_points():
        print(f"open3d_shapes.py: cannot read {path}", file=sys.stderr)
        return 2
    o3d.utility.random.seed(1)  # the same planes every run

    start = time.perf_counter()
    down, leaf = downsample_to_budget(cloud)
    t_voxel = time.perf_counter()
    down.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(16))
    t_normals = time.perf_counter()
    rest, planes = peel_planes(down, leaf, MAX_PLANES[shape])
    t_planes = time.perf_counter()

    line = {
        "tool": "open3d", "version": o3d.__version__, "file": os.path.basename(path),
        "shape": shape, "points_in": len(cloud.points), "points_used": len(down.points),
        "leaf": leaf, "planes": planes, "rest": len(rest.points),
        "fit_found": False if shape != "box" else None,
        "ms": (t_planes - start) * 1e3,
        "stages_ms": {"voxel": (t_voxel - start) * 1e3, "normals": (t_normals - t_voxel) * 1e3,
                      "planes": (t_planes - t_normals) * 1e3},
    }
    print(json.dumps(line, separators=(",", ":")))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
