// What solve_object measures of a fitted solid against the points: the share it explains, the
// share the points' own plane explains, how much of it a view covers, its flat faces, its kind.
#pragma once

#include <cstddef>
#include <vector>

#include "geometry/kdtree.hpp"
#include "geometry/point_cloud.hpp"
#include "pipeline/planes.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline::detail {

struct Verification {
  double explained = 0.0;  // share of points within the tolerance of the surface
  double rms = 0.0;        // RMS surface distance, each distance capped at the tolerance
};

// The share of the points (about `max_samples` of them, evenly strided) within `tolerance` of the
// solid's surface, and their RMS distance capped at it.
Verification verify(const PointList& cloud, const FittedSolid& solid, double tolerance,
                    std::size_t max_samples);

// Share of the points (the same sample as verify's) within `tolerance` of the plane that best
// fits those within it: the points' plane, refitted twice to its inliers.
double plane_share(const PointList& cloud, double tolerance, std::size_t max_samples);

// How far from a cone's or frustum's axis the points within `tolerance` of it reach (about
// `max_samples` of the points, evenly strided), as a share of its base radius (the larger of its
// radii); 0 for other solids and for no such point.
double rim_reach(const PointList& cloud, const FittedSolid& solid, double tolerance,
                 std::size_t max_samples);

// Share of the points (the same sample as verify's) within `tolerance` of a cylinder's side (its
// radius off the axis, between its caps and beyond `tolerance` of their planes: a cap's rim is
// the cap's), 0 for any other solid: a cylinder's radius and axis are the side's; a flat face
// whose outline a cap's circle holds (a tetrahedron's triangle, two boxes' tops) passes for its
// caps with almost no side.
double cylinder_side_share(const PointList& cloud, const FittedSolid& solid, double tolerance,
                           std::size_t max_samples);

// Share of the points (the same sample as verify's) lying more than `far` inside the solid whose
// nearest neighbours (`tree` over `cloud`) mostly lie inside beyond `tolerance` too: a stretch of
// surface the solid encloses without following it (a capsule's domes within a cylinder's caps, a
// torus's hole). A point counts only with a neighbour within `tolerance` (on a surface sampled
// at half of it or finer) and three quarters of its 8 nearest inside beyond `tolerance`: strays
// are far apart, and independent noise seldom puts most of a point's neighbours inside with it.
double off_surface_share(const PointList& cloud, const geometry::KdTree& tree,
                         const FittedSolid& solid, double far, double tolerance,
                         std::size_t max_samples);

// Share of the 26 direction sectors around the solid's centre (in its own frame: faces,
// edges and corners of a cube) that hold points. A convex solid seen whole is hit by rays
// from its centre in every direction, so every sector holds some of its surface; a single
// view leaves the far side's sectors empty.
double sector_coverage(const PointList& cloud, const Point& center, const Eigen::Matrix3d& axes,
                       double min_share);

// Share of the points off the solid's caps (true faces with their normal along its axis; a
// sphere has none) that lie on true flat faces their points fill (hull_fill of at least
// `min_fill`; a plane whose points trace an arc, traces_an_arc, is none: its fill is held as -1;
// `fills` holds each plane's, NaN until first needed: the same for every candidate
// solid, so computed once per object): a curved side is no face, so a cloud that is flat faces
// all round (an octahedron, whose corners ring some axis; a tetrahedron seen about a corner) is
// none. Only faces holding `large_share` of the points count for a cone or frustum: its side
// narrows towards the apex, where the strips RANSAC cuts along it are flat within the noise, but
// small. Zero where the caps hold most of the points: the side is too little to judge by, and
// the caps' rim passes for flat strips.
double flat_side_share(const FittedSolid& s, const PlaneSegmentation& planes,
                       const PointList& cloud, double cos_parallel, double cell, double min_fill,
                       double large_share, double arc_scatter, double arc_sagitta,
                       std::vector<double>& fills);

// Solids of one family (same_family), except a cylinder and a frustum whose side leans from its
// axis by more than `lean_degrees` and whose radii differ by more than the band its points are
// explained within (two tolerances): no cylinder then lies within the tolerance of that frustum
// all along, and the two are different answers (a cone lying on a table, its tip lost under a
// depth camera's noise, whose near side a tilted cylinder follows; a bottle's slight taper is a
// cylinder's).
bool same_kind(const FittedSolid& a, const FittedSolid& b, double tolerance, double lean_degrees);

}  // namespace cloudshape::pipeline::detail
