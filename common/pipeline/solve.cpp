#include "pipeline/solve.hpp"

#include <cmath>
#include <cstdio>

#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {
namespace {

double explained_fraction(const PointList& cloud, const FittedSolid& solid, double tolerance,
                          std::size_t max_samples) {
  if (cloud.empty()) return 0.0;
  const std::size_t step = std::max<std::size_t>(1, cloud.size() / std::max<std::size_t>(1, max_samples));
  std::size_t n = 0, inside = 0;
  for (std::size_t i = 0; i < cloud.size(); i += step, ++n)
    if (std::abs(solid.signed_distance(cloud[i])) <= tolerance) ++inside;
  return static_cast<double>(inside) / static_cast<double>(n);
}

// A solid far larger than the cloud can "explain" points lying near a few of its planes;
// no view of a real object makes it larger than the points' own extent allows.
bool plausible(const FittedSolid& s, double cloud_diameter, double max_size_ratio) {
  if (!s.center.allFinite() || !s.axes.allFinite()) return false;
  for (const auto& [name, value] : s.dimensions)
    if (!(value > 0.0) || !std::isfinite(value) || value > max_size_ratio * cloud_diameter)
      return false;
  return true;
}

}  // namespace

ObjectResult solve_object(const PointList& cloud, const PlaneSegmentation& planes,
                          const KeypointSet& keypoints, const Classification& classification,
                          double resolution, const config::SolveConfig& cfg) {
  ObjectResult out;
  out.keypoints = classification.counts;
  if (classification.candidates.empty()) {
    out.reason = classification.reason.empty() ? "no solid found" : classification.reason;
    return out;
  }
  const SolveInput input{cloud, planes, keypoints, classification, resolution, cfg};
  const double tolerance = cfg.inlier_distance * resolution;
  const double diameter = 2.0 * keypoints.reference.radius;
  std::vector<std::pair<FittedSolid, double>> fitted;
  double best = 0.0;
  for (Shape shape : classification.candidates) {
    auto solid = fit_solid(shape, input);
    if (!solid || !plausible(*solid, diameter, cfg.max_size_ratio)) continue;
    const double score =
        explained_fraction(cloud, *solid, tolerance, static_cast<std::size_t>(cfg.verify_samples));
    best = std::max(best, score);
    fitted.emplace_back(std::move(*solid), score);
  }
  const std::pair<FittedSolid, double>* chosen = nullptr;
  for (const auto& f : fitted)
    if (f.second >= best - cfg.preferred_margin) {
      chosen = &f;
      break;
    }
  if (!chosen || chosen->second < cfg.min_inlier_fraction) {
    char buf[160];
    if (chosen)
      std::snprintf(buf, sizeof buf, "no solid explains the points (best: %s, %.0f%% of points)",
                    shape_name(chosen->first.shape).c_str(), 100.0 * chosen->second);
    else
      std::snprintf(buf, sizeof buf, "no solid could be fitted");
    out.reason = buf;
    return out;
  }
  const FittedSolid& s = chosen->first;
  out.shape = shape_name(s.shape);
  out.dimensions = s.dimensions;
  out.center = s.center;
  out.axes = s.axes;
  out.confidence = std::clamp(chosen->second, 0.0, 1.0);
  return out;
}

}  // namespace cloudshape::pipeline
