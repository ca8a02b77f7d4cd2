// Which faces of a new shape hold the points of one view, and whether they determine the solid.
// new_shapes_view scores the views that do apart from those that cannot (one face, no cap).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "geometry/polygon.hpp"
#include "synth/ground_truth.hpp"

namespace cloudshape::bench {

// A face counts as seen when it holds at least this share of the view's points: less is a
// grazing sliver that fixes no plane or outline.
inline constexpr double kSeenFaceShare = 0.05;

struct ViewFaces {
  std::vector<std::size_t> counts;  // points per face, in the order the classifier names them
  bool determines = true;           // the faces seen fix the solid's shape (see each classifier)
  std::string note;                 // e.g. "faces seen: cap 1, sides 2 of 6" for --per-cloud
};

// A right prism (pose as synth::prism_mesh: the polygon in local y z, extruded along x from
// -height/2 to height/2). Determined when a cap (its outline: the polygon) and a side (the
// height) are seen; sides alone leave the cross-section open, a cap alone the height.
ViewFaces prism_view_faces(const PointList& points, const geometry::Polygon2& polygon, double height,
                           const synth::Pose& pose);

// A frustum (pose as synth::frustum_mesh: the larger end at the centre, x towards the smaller
// end `height` away). Determined when its side is seen: both radii lie on it.
ViewFaces frustum_view_faces(const PointList& points, double height, const synth::Pose& pose);

// A tetrahedron: determined when two or more faces are seen (two triangles sharing an edge hold
// all four corners); one face alone is a triangle, any apex above it.
ViewFaces tetrahedron_view_faces(const PointList& points, const std::array<Eigen::Vector3d, 4>& corners);

}  // namespace cloudshape::bench
