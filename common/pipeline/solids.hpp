// One fitter per solid behind one small interface: each turns the planes, key-points
// and points into the solid's dimensions, pose and a signed distance for verification.
#pragma once

#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "config/stage_configs.hpp"
#include "pipeline/classify.hpp"
#include "pipeline/cylinder_refine.hpp"
#include "pipeline/keypoints.hpp"
#include "pipeline/planes.hpp"
#include "pipeline/shape.hpp"

namespace cloudshape::pipeline {

namespace detail {
struct SurfaceSample {
  Point at = Point::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, sign arbitrary
};

// A straight tapered side fitted to the points alone, free of any face, and where the points end
// along its axis (heights `lo` < `hi` from cone.on_axis, a five-hundredth of the points trimmed
// at each end): a frustum's side, or a cone's whose apex its normals place badly under noise.
struct SideConeExtent {
  SideCone cone;
  double lo = 0.0, hi = 0.0;
};
}  // namespace detail

struct FittedSolid {
  Shape shape = Shape::unknown;
  std::vector<std::pair<std::string, double>> dimensions;  // INTERFACE.md names and order
  Point center = Point::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // rows as INTERFACE.md's axes[0..2]
  // A point well inside the solid, from which every direction meets its surface once. It is
  // the pose centre except where that lies on the surface (the cone's base centre).
  std::optional<Point> interior;
  // Shape extras of INTERFACE.md: a tetrahedron's corners and whether it is regular, a
  // prism's cross-section (counter-clockwise in the axes[1], axes[2] plane about center).
  std::vector<Point> vertices;
  bool regular = false;
  std::vector<Eigen::Vector2d> polygon;
  // A prism's sides that no face shows, placed on its cap's border alone: free lines fitted to
  // that border, each of which buys the solid a share of the points (solve.guessed_side_cost).
  int guessed_sides = 0;
  // Signed distance of a point to the solid's surface (negative inside); exact on the
  // surface, a lower bound away from it, which is all verification needs.
  std::function<double(const Point&)> signed_distance;
};

struct SolveInput {
  SolveInput(const PointList& cloud_, const PlaneSegmentation& planes_, const KeypointSet& keypoints_,
             const Classification& classification_, double resolution_,
             const config::SolveConfig& cfg_)
      : cloud(cloud_), planes(planes_), keypoints(keypoints_), classification(classification_),
        resolution(resolution_), cfg(cfg_) {}

  const PointList& cloud;
  const PlaneSegmentation& planes;
  const KeypointSet& keypoints;
  const Classification& classification;
  double resolution;
  const config::SolveConfig& cfg;
  const geometry::KdTree* tree = nullptr;  // over `cloud`, when the caller has one to share
  // The object was the only one in its cloud, and no sensor's viewpoint came with it (organized
  // clouds and lidar frames are scenes): nothing beside it could have hidden part of it.
  bool alone = false;

  // Normals over the whole cloud, estimated on first use and shared by the fitters that
  // need them (cylinder and cone without a face to seed them). Fitters may run on several
  // threads at once: the first to ask computes it, the others wait for it.
  const std::vector<detail::SurfaceSample>& cloud_normals() const;

  // fit_cylinder_from_side_normals, fitted on first use (as cloud_normals): the frustum's side
  // fit starts from it and the solver's second chance is it, on the same input.
  const std::optional<FittedSolid>& side_normals_cylinder() const;

  // The tapered side fitted to the points alone (detail::SideConeExtent), on first use: the
  // frustum's side, and the cone's where no face or apex from normals explains the points.
  const std::optional<detail::SideConeExtent>& side_cone() const;

 private:
  mutable std::once_flag normals_once_;
  mutable std::vector<detail::SurfaceSample> normals_;
  mutable std::once_flag side_normals_cylinder_once_;
  mutable std::optional<FittedSolid> side_normals_cylinder_;
  mutable std::once_flag side_cone_once_;
  mutable std::optional<detail::SideConeExtent> side_cone_;
};

std::optional<FittedSolid> fit_box(const SolveInput& in);
std::optional<FittedSolid> fit_tetrahedron(const SolveInput& in);
std::optional<FittedSolid> fit_pentagonal_prism(const SolveInput& in);
// A right prism of any other simple cross-section (a rectangle stays a box, a regular pentagon
// a pentagonal prism): every side face seen, ordered around the outline by where they meet.
std::optional<FittedSolid> fit_prism(const SolveInput& in);
std::optional<FittedSolid> fit_cylinder(const SolveInput& in);
// The cylinder with its axis from the surface normals alone, ignoring every flat face: the
// second chance when no solid explains the points, since a curved side seen from one side can
// break into strips flat enough to pass for faces, and the largest then poses as a cap.
std::optional<FittedSolid> fit_cylinder_from_side_normals(const SolveInput& in);
std::optional<FittedSolid> fit_cone(const SolveInput& in);
// The cone on the tapered side fitted to the points alone (SolveInput::side_cone), closed at the
// apex its radius comes to: where the points reach within solve.apex_gap of that apex (a
// frustum's side or a prism's few lidar rings fit a taper too, but stop short of where it would
// end) and it explains solve.side_fit_min_inlier_fraction of them, as the second chance must.
// Under a depth camera's noise a small cone's tangent planes meet far from its apex (fit_cone's
// base-free fit), and its noisy rim can pass for a polyhedron's corners; the side's own fit
// weighs every point.
std::optional<FittedSolid> fit_cone_from_side(const SolveInput& in);
// The cone a fitted frustum's side comes to: its base and axis, its apex where the side's radius
// comes to nothing (none for a frustum that does not narrow).
std::optional<FittedSolid> cone_of_frustum(const FittedSolid& frustum);
// The same, none where the points stop short of that apex (solve.apex_gap, solve.cone_tip_gap, as
// fit_cone's: a frustum's side seen from one side stops at its smaller rim). Under a depth camera's
// noise the points about a cone's tip lie off its axis on every side, and the side fitted through
// them ends in a top of a few millimetres.
std::optional<FittedSolid> cone_closing_frustum(const SolveInput& in, const FittedSolid& frustum);
std::optional<FittedSolid> fit_sphere_solid(const SolveInput& in);
// A truncated cone from a cap and its straight side; only where the taper is real
// (solve.frustum_min_taper) and the smaller end not a point.
std::optional<FittedSolid> fit_frustum(const SolveInput& in);

std::optional<FittedSolid> fit_solid(Shape shape, const SolveInput& in);

namespace detail {

// A solid with finite pose and positive, finite dimensions none larger than max_size_ratio times
// the cloud's enclosing diameter (a prism's side count aside).
bool plausible(const FittedSolid& s, double cloud_diameter, double max_size_ratio);

// True flat faces, largest first.
std::vector<const DetectedPlane*> faces_by_size(const PlaneSegmentation& planes);

// Mean of p.axis over the plane's inliers: where the face sits along `axis`.
double face_position(const PointList& cloud, const DetectedPlane& face, const Eigen::Vector3d& axis);

// Local-plane normals (12-neighbour PCA) of at most `max_samples` of the given points.
// `tree`, if given, is a search tree over `cloud`.
std::vector<SurfaceSample> sample_normals(const PointList& cloud,
                                          const std::vector<std::uint32_t>& points,
                                          std::size_t max_samples = 1500,
                                          const geometry::KdTree* tree = nullptr);

// The direction the normals are all perpendicular to (a cylinder's axis).
Eigen::Vector3d axis_from_normals(const std::vector<SurfaceSample>& samples);

// A cone from its side alone: the apex where the tangent planes meet, the axis the direction
// the points vary least in as seen from it (solid_cone.cpp); nothing for a cylinder's side.
std::optional<FittedSolid> cone_without_base(const SolveInput& in);

// Rows: axis, then two unit vectors completing a right-handed orthonormal frame.
Eigen::Matrix3d frame_from_axis(const Eigen::Vector3d& axis);

// Where the solid ends along `axis` on each side: the median position of the points in a
// slab `slab` thick at that end. Exact on a flat face, unbiased by noise, and the outer skin
// of a bulging one (as SOURCES.md measures "face to face"). A side with a detected face
// (its position given, else NaN) anchors its slab there rather than at the farthest point,
// so a few stray points beyond the face cannot move it. An end without a face (a single view:
// the visible faces just stop there) has its points spread evenly over the slab, where the
// median would fall half a slab short: it takes the open_quantile of the slab instead.
std::pair<double, double> slab_median_extent(const PointList& cloud, const Eigen::Vector3d& axis,
                                             double slab, double face_lo, double face_hi,
                                             double open_quantile);

// Where the points end along `direction` where no face of theirs ends them: the edge of a
// seen face against a hidden one. The open end of slab_median_extent (slab: cfg.face_slab
// of the extent along `direction`, at least two resolutions).
double open_end_support(const SolveInput& in, const Eigen::Vector3d& direction);

// A prism's axis by least squares: perpendicular to every side normal, along every cap normal
// (each weighted by its inliers), signed like `hint`.
Eigen::Vector3d extrusion_axis(const std::vector<const DetectedPlane*>& sides,
                               const std::vector<const DetectedPlane*>& caps, const Eigen::Vector3d& hint);

// Where an extruded solid (a prism) ends along its `axis`: at its caps where seen (largest
// first: noise may split a cap), else where the points end (slab_median_extent's open end).
std::pair<double, double> extrusion_extent(const SolveInput& in,
                                           const std::vector<const DetectedPlane*>& caps,
                                           const Eigen::Vector3d& axis);

// Points in planes (true faces or not) whose outward normal lies within `degrees` of one
// of `normals`: how much of the cloud a polyhedron with these face directions accounts
// for. Every plane on a polyhedron is one of its faces; the tangent strips RANSAC cuts
// from a curved surface point every way.
std::size_t points_on_planes_along(const PlaneSegmentation& planes,
                                   const std::vector<Eigen::Vector3d>& normals, double degrees);

// Share of the faces' points on faces whose normal lies within acos(cos_along) of none of
// `directions`: a polyhedron's every face is along one of its face directions, so faces along
// none (an octahedron's fourth direction, a pyramid's fifth face, a prism's slanted side under a
// box) say it is only a frame the points were fitted into.
// Share of (at most ~2000 of) the points within the inlier distance of the solid's surface: a
// quick rival test inside a fit (the solve's own verification comes after).
double explained_share(const SolveInput& in, const FittedSolid& solid);

double stray_face_share(const std::vector<const DetectedPlane*>& faces,
                        const std::vector<Eigen::Vector3d>& directions, double cos_along);

// A face along none of `directions` (within acos(cos_along)) that shares an edge
// (solve.box_edge_distance) with a face along one of them (within solve.parallel_degrees), at a slant (off parallel and off square
// by acos(cos_along)), the two comparably wide across it
// (solve.box_slanted_width_ratio): a prism's side meeting its neighbour at 60 or 120 deg.
bool slanted_neighbour_face(const SolveInput& in, const std::vector<const DetectedPlane*>& faces,
                            const std::vector<Eigen::Vector3d>& directions, double cos_along);

// How far from a box face's plane, along `axis`, a point lies beyond it: solve.box_step_depth of
// the points' extent along `axis`, at least inlier_distance resolutions (face_is_step's depth;
// faces_are_rectangles joins pieces of one face within it).
double step_depth(const SolveInput& in, const Eigen::Vector3d& axis);

// Whether `g` is a piece of the box face at `at` (face_position) along `direction`: along it
// (within acos(cos_along)) and within `depth` (step_depth) of it. RANSAC cuts a real box's
// bulging face into pieces a few millimetres apart and tilted a few degrees.
bool piece_of_face(const PointList& cloud, const DetectedPlane& g, const Eigen::Vector3d& direction,
                   double at, double depth, double cos_along);

// A face along one of `directions` (within acos(cos_along)) holding solve.box_step_min_share of
// the faces' points with more than solve.box_step_share of them on each side of it, farther than
// step_depth along that direction from the face's points: the inner face of an L or T, no face of
// a convex solid. Judged square to the direction, not along the face's own normal: a bulging
// face's pieces tilt, and their planes run through the faces square to them.
bool face_is_step(const SolveInput& in, const std::vector<const DetectedPlane*>& faces,
                  const std::vector<Eigen::Vector3d>& directions, double cos_along);

// Points that lie on none of the given faces, nor within `band` of their planes: noisy
// points of a face that fell outside its fine RANSAC band are still the face's.
std::vector<std::uint32_t> points_off_faces(const PointList& cloud,
                                            const std::vector<const DetectedPlane*>& faces,
                                            double band = 0.0);

// The straight side of a solid of revolution standing on `base`: at height h above the base's
// plane (along `axis`, into the solid) its distance from the axis is radius - slope * h;
// `centre` is the axis' foot in that plane, `top` the highest side point. Fitted (Gauss-Newton
// over axis position, radius and slope) to the points off the `flat` faces, between 5% and
// 95% of that height. Any sign of slope: the caller decides what it may be.
struct ConicalSide {
  Point centre = Point::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double radius = 0.0;
  double slope = 0.0;
  double top = 0.0;
};
std::optional<ConicalSide> fit_conical_side(const SolveInput& in, const DetectedPlane& base,
                                            const std::vector<const DetectedPlane*>& flat);

}  // namespace detail
}  // namespace cloudshape::pipeline
