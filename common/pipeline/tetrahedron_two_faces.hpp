// Any tetrahedron from two of its faces, as a single view shows them (two or three, each whole):
// the edge the two share and each one's third corner, from lines along their borders.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "pipeline/solids.hpp"

namespace cloudshape::pipeline::detail {

// The area of the convex hull of a face's points, in the face's plane.
double face_hull_area(const PointList& cloud, const DetectedPlane& face);

// The four corners from the two largest of `faces` (by points; no closer to parallel than
// `cos_parallel`): they share an edge on the line where their planes cross, between where their
// points end along it; each face's third corner is where its other two edges meet, lines
// through its outermost points (first guess: its point farthest from the shared line). Each face
// must be the triangle so found, its points' hull within in.cfg.triangle_fill_tolerance of the
// triangle's area (a box's rectangle holds twice its triangle), and each the outside of the
// solid (the other's corner behind it). Nothing otherwise.
std::optional<std::array<Point, 4>> tetrahedron_from_two_faces(
    const SolveInput& in, const std::vector<const DetectedPlane*>& faces, double cos_parallel);

}  // namespace cloudshape::pipeline::detail
