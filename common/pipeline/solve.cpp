#include "pipeline/solve.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

#include "geometry/oriented_box.hpp"
#include "pipeline/container.hpp"
#include "pipeline/free_space.hpp"
#include "pipeline/scan_fit.hpp"
#include "pipeline/solid_checks.hpp"
#include "pipeline/solids.hpp"
#include "pipeline/view_noise.hpp"

namespace cloudshape::pipeline {
namespace {

using detail::flat_side_share;
using detail::plane_share;
using detail::same_kind;
using detail::sector_coverage;
using detail::Verification;
using detail::verify;

Extent extent_of(const PointList& cloud, const std::vector<Eigen::Matrix3d>& hints,
                 const config::SolveConfig& cfg, parallel::ThreadPool* pool) {
  const geometry::OrientedBox box = geometry::oriented_bounding_box(
      cloud, hints, static_cast<std::size_t>(std::max<std::int64_t>(3, cfg.extent_hull_samples)),
      pool);
  return {box.center, box.axes, box.size};
}

// The radius of a ball about the solid's centre that holds it: the sum of its lengths (a box's
// half-diagonal is less, a cone's apex and rim lie within height plus radius of its base centre),
// or a prism's cross-section radius plus its height.
double reach_of(const FittedSolid& s) {
  double reach = 0.0;
  for (const auto& [name, value] : s.dimensions)
    if (name != "sides") reach += value;
  if (!s.polygon.empty()) {
    double widest = 0.0;
    for (const Eigen::Vector2d& v : s.polygon) widest = std::max(widest, v.norm());
    reach = std::max(reach, widest + s.dimensions.front().second);
  }
  return reach;
}

}  // namespace

namespace detail {

// A frustum is never chosen where another solid explains within `margin` of the most (below), so
// it counts only through the most it may raise: not where another explains within `margin` of
// every point, and those within `margin` of the most are the same whatever the frustum explains
// (at most every point: the same set at both ends of that range is the same set all along it).
bool frustum_may_matter(const std::vector<double>& explained, double margin) {
  double most = -1.0;
  for (double e : explained) most = std::max(most, e);
  const double all_but_margin = 1.0 - margin;
  if (most < all_but_margin) return true;
  for (double e : explained) {
    if ((e < most - margin) != (e < all_but_margin)) return true;
  }
  return false;
}

}  // namespace detail

ObjectResult solve_object(const PointList& cloud, const PlaneSegmentation& planes,
                          const KeypointSet& keypoints, const Classification& classification,
                          double resolution, const config::SolveConfig& cfg,
                          const geometry::KdTree* tree, const std::optional<Point>& viewpoint,
                          std::size_t objects_in_cloud, std::uint32_t scan_lines,
                          parallel::ThreadPool* pool, const PointList* returns_about) {
  ObjectResult out;
  out.keypoints = classification.counts;
  // Even with no solid, where the points are is worth telling (a consumer tracks or avoids them).
  for (const Point& p : cloud) out.center += p / static_cast<double>(std::max<std::size_t>(1, cloud.size()));
  // No solid named, for `reason`: the extent is the points' own.
  const auto unknown = [&](std::string reason) {
    out.reason = std::move(reason);
    out.extent = extent_of(cloud, {}, cfg, pool);
    return out;
  };
  if (classification.candidates.empty()) {
    return unknown(classification.reason.empty() ? "no solid found" : classification.reason);
  }
  // On two scan lines only a sphere is determined; one line (segment.scan_object_min_beams
  // below 2) fixes no solid at all.
  const bool sphere_only =
      scan_lines > 0 && static_cast<std::int64_t>(scan_lines) < cfg.solid_min_scan_lines;
  const auto lines = [scan_lines] {
    return "seen on " + std::to_string(scan_lines) + " scan line" + (scan_lines == 1 ? "" : "s");
  };
  // A reason, preceded by the scan lines where the object is a lidar's.
  const auto on_lines = [&](const std::string& reason) {
    return (scan_lines > 0 ? lines() + ": " : std::string()) + reason;
  };
  // Beside a circular face (a lid) the sphere is no candidate, but in a view (a sensor's viewpoint
  // known) a small ball's cap under a depth camera's noise lies within a face's band and reads as
  // one: there the sphere is tried too, after the solids the face calls for (which keep ties) and
  // before any other prism.
  std::vector<Shape> offered = classification.candidates;
  if (classification.cap_plane && viewpoint &&
      std::find(offered.begin(), offered.end(), Shape::sphere) == offered.end())
    offered.insert(std::find(offered.begin(), offered.end(), Shape::prism), Shape::sphere);
  std::vector<Shape> candidates;
  for (Shape shape : offered) {
    if (!sphere_only || (shape == Shape::sphere && scan_lines >= 2)) candidates.push_back(shape);
  }
  if (candidates.empty()) {
    return unknown(
        scan_lines == 1
            ? lines() + ": no solid is determined"
            : lines() + ": only a sphere is determined, and the points were not classed as one");
  }
  SolveInput input{cloud, planes, keypoints, classification, resolution, cfg};
  input.tree = tree;
  input.alone = !viewpoint && objects_in_cloud == 1;
  const double tolerance = cfg.inlier_distance * resolution;
  const double diameter = 2.0 * keypoints.reference.radius;
  std::vector<std::pair<FittedSolid, Verification>> fitted;
  double best = 0.0;
  const double cos_parallel = std::cos(cfg.parallel_degrees * 3.14159265358979323846 / 180.0);
  std::vector<double> fills(planes.planes.size(), std::numeric_limits<double>::quiet_NaN());
  const auto admissible = [&](const std::optional<FittedSolid>& solid) {
    return solid && detail::plausible(*solid, diameter, cfg.max_size_ratio) &&
           (solid->shape != Shape::cylinder ||
            detail::cylinder_side_share(cloud, *solid, tolerance,
                                        static_cast<std::size_t>(cfg.verify_samples)) >=
                cfg.cylinder_min_side_share) &&
           ((solid->shape != Shape::cone && solid->shape != Shape::frustum) ||
            !(cfg.tapered_min_rim_reach > 0.0) ||
            detail::rim_reach(cloud, *solid, tolerance,
                              static_cast<std::size_t>(cfg.verify_samples)) >=
                cfg.tapered_min_rim_reach) &&
           flat_side_share(*solid, planes, cloud, cos_parallel,
                           cfg.flat_face_fill_cells * resolution, cfg.flat_face_min_fill,
                           cfg.side_face_min_share, cfg.arc_max_scatter_cells,
                           cfg.arc_min_sagitta_cells, fills) <= cfg.curved_side_flat_share;
  };
  // Each candidate's fit in its own slot, on the pool (the fits share only SolveInput's
  // once-computed normals), then admitted and verified in candidate order (the order keeps ties);
  // the frustum's last, and only where it can change the choice (detail::frustum_may_matter): it
  // costs as much as the others.
  std::vector<std::optional<std::pair<FittedSolid, Verification>>> fit_of(candidates.size());
  const auto admit = [&](std::size_t i, std::optional<FittedSolid>& solid) {
    if (!admissible(solid)) return;
    const Verification v =
        verify(cloud, *solid, tolerance, static_cast<std::size_t>(cfg.verify_samples));
    fit_of[i].emplace(std::move(*solid), v);
  };
  // Another fit of candidate i's solid, kept where it explains more points than the slot holds.
  const auto keep_if_more = [&](std::size_t i, std::optional<FittedSolid>& solid) {
    if (!admissible(solid)) return;
    const Verification v =
        verify(cloud, *solid, tolerance, static_cast<std::size_t>(cfg.verify_samples));
    if (v.explained > (fit_of[i] ? fit_of[i]->second.explained : 0.0))
      fit_of[i].emplace(std::move(*solid), v);
  };
  std::vector<std::size_t> others;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i] != Shape::frustum) others.push_back(i);
  }
  std::vector<std::optional<FittedSolid>> solid_of(candidates.size());
  parallel::for_blocks(pool, others.size(), 1, [&](std::size_t begin, std::size_t) {
    solid_of[others[begin]] = fit_solid(candidates[others[begin]], input);
  });
  for (std::size_t i : others) admit(i, solid_of[i]);
  const auto explained_by_fits = [&] {
    std::vector<double> explained;
    for (const auto& f : fit_of) {
      if (f) explained.push_back(f->second.explained);
    }
    return explained;
  };
  // A cone whose fits explain less than the second chance must gets its side fitted to the points
  // alone (fit_cone_from_side), where that can change the choice as the frustum's must; so does a
  // cone explaining enough to be an answer (cfg.min_inlier_fraction) but out of the running
  // (cfg.preferred_margin below the most): a small cone's apex misplaced under a depth camera's
  // noise, while a cylinder explained its points within the tolerance (two resolutions, three
  // noises each). The side fit costs as much as the frustum's, which then shares it; a cone that no
  // fit could place, beside a solid explaining nearly every point, is not refitted (a noisy 100k
  // cylinder or ball would pay 15-25% more for nothing).
  // Where the key-points' class is a polyhedron and its solid was fitted, the cone is only a rival
  // (fit_cone computes no normals there either); a class whose own solid failed says nothing.
  const bool polyhedron_fitted =
      polyhedron_by_corners(candidates.front()) && fit_of.front().has_value();
  for (std::size_t i = 0; i < candidates.size() && !polyhedron_fitted; ++i) {
    if (candidates[i] != Shape::cone) continue;
    const double cone_share = fit_of[i] ? fit_of[i]->second.explained : 0.0;
    const std::vector<double> explained = explained_by_fits();
    const double most =
        explained.empty() ? 0.0 : *std::max_element(explained.begin(), explained.end());
    const bool refit =
        cone_share >= cfg.min_inlier_fraction && cone_share < most - cfg.preferred_margin;
    if (!refit && (cone_share >= cfg.side_fit_min_inlier_fraction ||
                   !detail::frustum_may_matter(explained, cfg.preferred_margin)))
      continue;
    std::optional<FittedSolid> from_side = fit_cone_from_side(input);
    keep_if_more(i, from_side);
  }
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i] != Shape::frustum) continue;
    if (!detail::frustum_may_matter(explained_by_fits(), cfg.preferred_margin)) continue;
    solid_of[i] = fit_solid(candidates[i], input);
    admit(i, solid_of[i]);
    // The cone the frustum's side comes to (cone_closing_frustum) is the cone's fit too, where it
    // explains more than the cone's own: a small cone whose tip the noise blurred is fitted by a
    // frustum with a top of about the tolerance, and the frustum is chosen only where no solid with
    // a parameter fewer explains nearly as much.
    const auto cone_slot = std::find(candidates.begin(), candidates.end(), Shape::cone);
    if (!fit_of[i] || cone_slot == candidates.end()) continue;
    std::optional<FittedSolid> closed = cone_closing_frustum(input, fit_of[i]->first);
    keep_if_more(static_cast<std::size_t>(cone_slot - candidates.begin()), closed);
  }
  // What a solid explains, less what its free lines bought: a prism side no face shows is fitted
  // to its cap's border alone, and a real box's ragged or rounded border gives such a prism a few
  // points more than the box's faces do (cfg.guessed_side_cost each).
  const auto score = [&](const std::pair<FittedSolid, Verification>& f) {
    return f.second.explained - cfg.guessed_side_cost * static_cast<double>(f.first.guessed_sides);
  };
  for (auto& f : fit_of) {
    if (!f) continue;
    best = std::max(best, score(*f));
    fitted.push_back(std::move(*f));
  }
  // Among the solids explaining nearly the most points, the closest fit wins: on a sparse
  // cloud a cylinder explains a pentagonal prism's points too, but not as closely. The
  // key-point class (first candidate) keeps ties.
  // A frustum only where no other solid is among them: a cone cut short or a cylinder explains
  // nearly as much with one parameter fewer.
  const std::pair<FittedSolid, Verification>* chosen = nullptr;
  for (bool frustum_too : {false, true}) {
    for (const auto& f : fitted) {
      if (score(f) < best - cfg.preferred_margin) continue;
      if (f.first.shape == Shape::frustum && !frustum_too) continue;
      if (!chosen || f.second.rms < chosen->second.rms * (1.0 - cfg.closer_fit_margin)) chosen = &f;
    }
    if (chosen) break;
  }
  // Nor where another solid explaining enough points (cfg.min_inlier_fraction) fits them more
  // closely: the frustum's extra parameter then only stretches its band over more of them (a
  // ball on a few lidar rings).
  if (chosen && chosen->first.shape == Shape::frustum) {
    const std::pair<FittedSolid, Verification>* closer = nullptr;
    for (const auto& f : fitted) {
      if (f.first.shape == Shape::frustum || f.second.explained < cfg.min_inlier_fraction ||
          !(f.second.rms < chosen->second.rms))
        continue;
      if (!closer || f.second.explained > closer->second.explained) closer = &f;
    }
    if (closer) chosen = closer;
  }
  // The second chance fits axis, position and radius to the points alone, free of any face or
  // key-point: it must explain more of them (cfg.side_fit_min_inlier_fraction). A frustum is
  // the answer only where no cylinder explains the points: the second chance is tried against it
  // too, and a cylinder explaining nearly as many (cfg.preferred_margin) stands. So is a sphere or
  // cylinder that leaves many points unexplained (cfg.second_chance_round_below): a can seen over
  // part of its arc, its points coarse or noisy, passes for part of a ball, and a cylinder on a
  // flat-looking strip taken for its cap is tilted; the freer cylinder must explain more.
  const bool frustum = chosen && chosen->first.shape == Shape::frustum;
  const bool weak_round =
      chosen && (chosen->first.shape == Shape::sphere || chosen->first.shape == Shape::cylinder) &&
      chosen->second.explained < cfg.second_chance_round_below;
  if (!sphere_only &&
      (!chosen || chosen->second.explained < cfg.min_inlier_fraction || frustum || weak_round)) {
    if (auto second = input.side_normals_cylinder(); admissible(second)) {
      const Verification v =
          verify(cloud, *second, tolerance, static_cast<std::size_t>(cfg.verify_samples));
      const double to_beat =
          !chosen ? 0.0 : frustum ? chosen->second.explained - cfg.preferred_margin : chosen->second.explained;
      if (v.explained >= std::max(cfg.min_inlier_fraction, cfg.side_fit_min_inlier_fraction) &&
          (!chosen || v.explained > to_beat)) {
        fitted.emplace_back(std::move(*second), v);
        chosen = &fitted.back();
      }
    }
  }
  // A round solid whose points a plane explains as well (within cfg.preferred_margin) shows no
  // curvature beyond the tolerance: which way its surface bends, and how much, is not measured
  // (one face of a tetrahedron under a depth camera's noise passed for a flat cone's hollow, and
  // so for a container). In a depth camera's view the plane's band is at least
  // cfg.flat_noise_sigmas of the noise along the rays (nearest points in space read a third of a
  // far face's noise: a cone's base disc 1.8 m off passed for a cylinder); not in a lidar's, whose
  // nearest rays run along one ring.
  if (chosen && is_round(chosen->first.shape) &&
      chosen->second.explained >= cfg.min_inlier_fraction) {
    double band = tolerance;
    const std::optional<Point> camera = noise_viewpoint(viewpoint, scan_lines);
    if (camera && cfg.flat_noise_sigmas > 0.0) {
      const double noise = planes.view_noise > 0.0
                               ? planes.view_noise
                               : noise_along_view(cloud, *camera, kViewNoiseRays);
      band = std::max(band, cfg.flat_noise_sigmas * noise);
    }
    const double flat = plane_share(cloud, band, static_cast<std::size_t>(cfg.verify_samples));
    if (flat >= chosen->second.explained - cfg.preferred_margin) {
      char buf[160];
      std::snprintf(
          buf, sizeof buf, "a plane explains the points as well as a %s (%.0f%% and %.0f%%)",
          shape_name(chosen->first.shape).c_str(), 100.0 * flat, 100.0 * chosen->second.explained);
      return unknown(on_lines(buf));
    }
  }
  // The chosen round solid seen from its hollow side is the inside of a container, which is what
  // the points show (container.hpp); on two scan lines neither is determined.
  bool contained = false;
  if (chosen && viewpoint && seen_from_inside(cloud, chosen->first, *viewpoint, 0.5 * resolution, cfg)) {
    if (sphere_only) {
      return unknown(lines() + ": a hollow side, and no container is determined");
    }
    auto container = container_of_hollow(cloud, chosen->first, cfg);
    if (container && detail::plausible(*container, diameter, cfg.max_size_ratio)) {
      const Verification v = verify(cloud, *container, tolerance, static_cast<std::size_t>(cfg.verify_samples));
      fitted.emplace_back(std::move(*container), v);
      chosen = &fitted.back();
      contained = true;
    }
  }
  // Two solids of different kinds (same_kind) explaining as many points (cfg.preferred_margin), the
  // other as closely or closer (cfg.ambiguity_rms_ratio of the chosen's RMS): the points do not
  // tell them apart. Where the key-points found a polyhedron's corners and its solid was fitted,
  // their class breaks the tie (a noisy box's corners outlast its flat faces); where they found
  // only a view's border points (every single view has them: "cylinder"), or corners whose solid
  // failed (a small ball's noisy rim gave a tetrahedron's), it is no evidence (small balls far off
  // under a depth camera's noise came out cylinders), and neither solid is named. (A container's
  // rivals were fitted to its inside as an outside.)
  if (chosen && !contained && cfg.ambiguity_rms_ratio > 0.0 &&
      !(polyhedron_fitted && polyhedron_by_corners(classification.shape)) &&
      chosen->second.explained >= cfg.min_inlier_fraction) {
    for (const auto& f : fitted) {
      if (same_kind(f.first, chosen->first, tolerance, cfg.parallel_degrees) ||
          score(f) < score(*chosen) - cfg.preferred_margin ||
          !(f.second.rms <= cfg.ambiguity_rms_ratio * chosen->second.rms))
        continue;
      char buf[200];
      std::snprintf(buf, sizeof buf, "a %s and a %s explain the points alike (%.0f%% and %.0f%%)",
                    shape_name(chosen->first.shape).c_str(), shape_name(f.first.shape).c_str(),
                    100.0 * chosen->second.explained, 100.0 * f.second.explained);
      return unknown(on_lines(buf));
    }
  }
  if (!chosen || chosen->second.explained < cfg.min_inlier_fraction) {
    char buf[160];
    if (chosen)
      std::snprintf(buf, sizeof buf, "no solid explains the points (best: %s, %.0f%% of points)",
                    shape_name(chosen->first.shape).c_str(), 100.0 * chosen->second.explained);
    else
      std::snprintf(buf, sizeof buf, "no solid could be fitted");
    return unknown(sphere_only ? lines() + ", only a sphere tried: " + buf : std::string(buf));
  }
  // The share of direction sectors the chosen solid's points cover, once per solid chosen (its
  // place in `fitted`, which later fits may move): the test below and the result's `partial`
  // read it.
  std::size_t covered = std::numeric_limits<std::size_t>::max();
  double coverage = 0.0;
  const auto coverage_of = [&](const std::pair<FittedSolid, Verification>* c) {
    const auto slot = static_cast<std::size_t>(c - fitted.data());
    if (covered != slot) {
      const FittedSolid& f = c->first;
      coverage =
          sector_coverage(cloud, f.interior.value_or(f.center), f.axes, cfg.sector_min_share);
      covered = slot;
    }
    return coverage;
  };
  // A solid named for an object seen all round and alone in its cloud follows all of its surface:
  // a stretch of surface well inside it (a capsule's domes within a cylinder's caps, a pentagonal
  // prism's slanted faces within a box) says the object is none of the solids, however many
  // points the rest explains. Not in a single view: a real milk carton seen from one side leaves
  // its gable inside its box as a capsule leaves its domes inside a cylinder (a fifth of the
  // points), and a real box's view its slightly bowed faces as much; a box is what such a carton
  // is taken for. Nor in a scene, where a neighbour's fragment or the table's band
  // joined to an object lies off it too.
  if (input.alone && cfg.off_surface_max_share > 0.0 && coverage_of(chosen) >= 1.0) {
    std::optional<geometry::KdTree> own_tree;
    const geometry::KdTree& near_tree = tree != nullptr ? *tree : own_tree.emplace(cloud);
    const double off = detail::off_surface_share(cloud, near_tree, chosen->first,
                                                 cfg.off_surface_distance * tolerance, tolerance,
                                                 static_cast<std::size_t>(cfg.verify_samples));
    if (off > cfg.off_surface_max_share) {
      char buf[200];
      std::snprintf(buf, sizeof buf,
                    "the best solid (%s) encloses a surface it does not follow: %.0f%% of the "
                    "points lie well inside it",
                    shape_name(chosen->first.shape).c_str(), 100.0 * off);
      return unknown(buf);
    }
  }
  // A lidar object's solid must lie within the points' own noise of them: on a few scan lines a
  // wrong solid still passes within inlier_distance of most points (the spacing along a ring sets
  // the resolution, the ranging noise does not shrink with it), but it leaves them scattered by
  // several times the noise each ring shows along itself, where the right one does not.
  if (scan_lines > 0 && viewpoint && cfg.scan_noise_ratio > 0.0) {
    const double noise = scan_line_noise(cloud, *viewpoint);
    const double scatter = scatter_about(cloud, chosen->first);
    // A noise-free ring's neighbours are collinear on a flat face: below this share of the point
    // spacing a scatter is the fit's own arithmetic.
    constexpr double kScatterFloorSpacings = 0.01;
    if (scatter > std::max(cfg.scan_noise_ratio * noise, kScatterFloorSpacings * resolution)) {
      char buf[200];
      std::snprintf(buf, sizeof buf,
                    ": the best solid (%s) leaves the points %.1f times their noise from it",
                    shape_name(chosen->first.shape).c_str(), noise > 0.0 ? scatter / noise : 0.0);
      return unknown(lines() + buf);
    }
  }
  // A lidar object's solid must stand where the sensor saw no free space: on a few scan lines a fit
  // is free between and beyond them (a ball 0.5 m wide for a can 0.35 m wide, a box across a wall
  // strip), and the frame's rays beside and behind it measure where it is not. The right solid lets
  // none of the rays that cross it through (a depth image's outline, seen densely, bounds its fit
  // itself).
  const bool weigh_free_space =
      scan_lines > 0 && viewpoint && returns_about != nullptr && cfg.free_space_max_share > 0.0;
  const auto rays_through = [&](const FittedSolid& f) {
    return rays_through_solid(*returns_about, *viewpoint, f.signed_distance, f.center, reach_of(f),
                              tolerance);
  };
  const auto seen_through = [&](const RaysThroughSolid& rays) {
    return static_cast<double>(rays.through) >
           cfg.free_space_max_share * static_cast<double>(rays.crossing);
  };
  // On a few scan lines a cone's tip lies between them, unseen (fit_cone's test that a side seen at
  // all reaches its tip holds for a dense sensor only): there the rays, not the points, say whether
  // the tip is there, and a frustum whose cone explains as many points (cfg.preferred_margin) and
  // stands where the sensor saw no free space is that cone, a parameter fewer (and weighed
  // already).
  bool weighed = false;
  if (weigh_free_space && chosen->first.shape == Shape::frustum) {
    if (std::optional<FittedSolid> cone = cone_of_frustum(chosen->first)) {
      const Verification v =
          verify(cloud, *cone, tolerance, static_cast<std::size_t>(cfg.verify_samples));
      if (v.explained >= chosen->second.explained - cfg.preferred_margin &&
          !seen_through(rays_through(*cone))) {
        fitted.emplace_back(std::move(*cone), v);
        chosen = &fitted.back();
        weighed = true;
      }
    }
  }
  if (weigh_free_space && !weighed) {
    const FittedSolid& f = chosen->first;
    const RaysThroughSolid rays = rays_through(f);
    if (seen_through(rays)) {
      char buf[200];
      std::snprintf(buf, sizeof buf,
                    ": the sensor saw through the best solid (%s): %.0f%% of the rays crossing it "
                    "return from beyond it",
                    shape_name(f.shape).c_str(),
                    100.0 * static_cast<double>(rays.through) / static_cast<double>(rays.crossing));
      return unknown(lines() + buf);
    }
  }
  const FittedSolid& s = chosen->first;
  out.shape = shape_name(s.shape);
  out.dimensions = s.dimensions;
  out.center = s.center;
  out.axes = s.axes;
  out.vertices = s.vertices;
  out.regular = s.regular;
  out.polygon = s.polygon;
  // The solid's own frame is usually the tightest one for its points.
  out.extent = extent_of(cloud, {s.axes}, cfg, pool);
  // A single view cannot confirm the hidden side: the dimensions describe what was seen,
  // and the confidence drops with the share of the solid that was not seen.
  out.partial = coverage_of(chosen) < 1.0;
  out.confidence =
      std::clamp(chosen->second.explained * (0.5 + 0.5 * coverage_of(chosen)), 0.0, 1.0);
  return out;
}

}  // namespace cloudshape::pipeline
