// Shared by the per-shape positive tests: a cloud of one solid under a condition (noise,
// outliers, one camera), recognition, and the errors of the result against the ground truth.
#include "positive_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "config/pipeline_config.hpp"
#include "pipeline/recognize.hpp"
#include "synth/pose.hpp"
#include "synth/solid_geometry.hpp"
#include "synth/synthetic_cloud.hpp"

namespace cloudshape::positive {
namespace {

constexpr double kPi = 3.14159265358979323846;

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b, bool signed_axis) {
  double c = a.normalized().dot(b.normalized());
  if (!signed_axis) c = std::abs(c);
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / kPi;
}

Eigen::Vector3d row(const Eigen::Matrix3d& axes, int i) { return axes.row(i).transpose(); }

// The largest angle from one of `truth` to the nearest of `got`: both sets of directions are
// the solid's symmetric features, so which one a frame starts from does not matter.
double set_angle_deg(const std::vector<Eigen::Vector3d>& truth,
                     const std::vector<Eigen::Vector3d>& got) {
  double worst = 0.0;
  for (const auto& t : truth) {
    double best = 180.0;
    for (const auto& g : got) best = std::min(best, angle_deg(t, g, true));
    worst = std::max(worst, best);
  }
  return worst;
}

std::vector<Eigen::Vector3d> tetrahedron_directions(const Eigen::Matrix3d& axes) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& v : synth::tetrahedron_vertices(1.0))
    out.push_back(axes.transpose() * v.normalized());
  return out;
}

std::vector<Eigen::Vector3d> prism_side_normals(const Eigen::Matrix3d& axes) {
  const auto v = synth::pentagon_vertices(1.0);
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < 5; ++k)
    out.push_back(axes.transpose() * (v[k] + v[(k + 1) % 5]).normalized());
  return out;
}

double axes_error_deg(const pipeline::ObjectResult& got, const synth::SolidSpec& truth) {
  const Eigen::Matrix3d& t = truth.pose.axes;
  switch (truth.kind) {
    case synth::ShapeKind::sphere:
      return 0.0;
    case synth::ShapeKind::box:
      return std::max({angle_deg(row(got.axes, 0), row(t, 0), false),
                       angle_deg(row(got.axes, 1), row(t, 1), false),
                       angle_deg(row(got.axes, 2), row(t, 2), false)});
    case synth::ShapeKind::cylinder:
      return angle_deg(row(got.axes, 0), row(t, 0), false);
    case synth::ShapeKind::cone:
      return angle_deg(row(got.axes, 0), row(t, 0), true);
    case synth::ShapeKind::pentagonal_prism:
      // The prism reports one side's outward normal as axes[1] (any of the five).
      return std::max(angle_deg(row(got.axes, 0), row(t, 0), false),
                      set_angle_deg({row(got.axes, 1)}, prism_side_normals(t)));
    case synth::ShapeKind::tetrahedron:
      return set_angle_deg(tetrahedron_directions(t), tetrahedron_directions(got.axes));
  }
  return 180.0;
}

const config::PipelineConfig& shipped_config() {
  static const config::PipelineConfig cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  return cfg;
}

}  // namespace

Condition noisy() { return {"noise 0.5%", 10000, 0.005, 0.0, std::nullopt}; }

Condition noisy_with_outliers() {
  return {"noise 0.5% + 3% outliers", 10000, 0.005, 0.03, std::nullopt};
}

Condition seen_from(const Eigen::Vector3d& direction, double noise) {
  return {noise > 0 ? "single view, noise " + std::to_string(noise * 100).substr(0, 3) + "%"
                    : "single view",
          10000, noise, 0.0, direction};
}

PointList make_cloud(const synth::SolidSpec& truth, const Condition& condition,
                     std::uint64_t seed) {
  const double size = synth::characteristic_size(truth);
  synth::CloudOptions options;
  options.points = condition.points;
  options.noise_sigma = condition.noise * size;
  options.outlier_fraction = condition.outliers;
  if (condition.view_direction)
    options.view = truth.pose.center + 3.0 * size * condition.view_direction->normalized();
  return synth::make_synthetic_cloud({truth}, options, seed).points;
}

Errors errors_of(const pipeline::ObjectResult& got, const synth::SolidSpec& truth) {
  Errors e;
  for (std::size_t d = 0; d < truth.dimensions.size(); ++d) {
    const bool named =
        d < got.dimensions.size() && got.dimensions[d].first == truth.dimensions[d].first;
    e.dimensions.push_back(
        named ? std::abs(got.dimensions[d].second / truth.dimensions[d].second - 1.0)
              : std::numeric_limits<double>::infinity());
  }
  e.center = (got.center - truth.pose.center).norm() / synth::characteristic_size(truth);
  e.axes_deg = axes_error_deg(got, truth);
  return e;
}

void Worst::add(const Errors& e) {
  dimensions.resize(std::max(dimensions.size(), e.dimensions.size()), 0.0);
  for (std::size_t d = 0; d < e.dimensions.size(); ++d)
    dimensions[d] = std::max(dimensions[d], e.dimensions[d]);
  center = std::max(center, e.center);
  axes_deg = std::max(axes_deg, e.axes_deg);
  ++runs;
}

void Worst::print(const std::string& shape, const std::string& condition) const {
  std::string dims;
  for (double d : dimensions) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%s%.2f%%", dims.empty() ? "" : " ", 100.0 * d);
    dims += buf;
  }
  std::printf(
      "[measured] %-16s %-26s %d runs: worst dimensions %s, centre %.2f%% of size, axes %.2f deg\n",
      shape.c_str(), condition.c_str(), runs, dims.c_str(), 100.0 * center, axes_deg);
}

Errors expect_recognised(const PointList& cloud, const synth::SolidSpec& truth, bool partial,
                         const Tolerance& tolerance, const std::string& trace) {
  SCOPED_TRACE(trace);
  const auto result = pipeline::recognize_cloud(cloud, shipped_config(), trace);
  EXPECT_EQ(result.objects.size(), 1u);
  if (result.objects.empty()) return {};
  const pipeline::ObjectResult& got = result.objects.front();
  EXPECT_EQ(got.shape, synth::to_string(truth.kind)) << got.reason;
  if (got.shape != synth::to_string(truth.kind)) return {};
  EXPECT_EQ(got.partial, partial);
  const Errors e = errors_of(got, truth);
  for (std::size_t d = 0; d < e.dimensions.size(); ++d)
    EXPECT_LE(e.dimensions[d], tolerance.dimension)
        << truth.dimensions[d].first << ": got "
        << (d < got.dimensions.size() ? got.dimensions[d].second : 0.0) << ", true "
        << truth.dimensions[d].second;
  EXPECT_LE(e.center, tolerance.center) << "centre off by this share of the size";
  EXPECT_LE(e.axes_deg, tolerance.axes_deg) << "axes off by this many degrees";
  return e;
}

void check_seeds(const std::vector<std::uint64_t>& seeds, const SolidMaker& solid,
                 const ConditionMaker& condition, bool partial, const Tolerance& tolerance) {
  Worst worst;
  std::string shape, name;
  for (const std::uint64_t seed : seeds) {
    std::mt19937_64 rng(seed);
    const synth::SolidSpec truth = solid(rng);
    const Condition c = condition(truth, rng);
    shape = synth::to_string(truth.kind);
    name = c.name;
    const PointList cloud = make_cloud(truth, c, rng());
    const Errors e = expect_recognised(cloud, truth, partial, tolerance,
                                       shape + ", " + c.name + ", seed " + std::to_string(seed));
    if (!e.dimensions.empty()) worst.add(e);
  }
  worst.print(shape, name);
}

Eigen::Vector3d from_axis(const synth::SolidSpec& truth, double degrees, std::mt19937_64& rng) {
  const double turn = std::uniform_real_distribution<double>(0.0, 2.0 * kPi)(rng);
  const double a = degrees * kPi / 180.0;
  const Eigen::Matrix3d& t = truth.pose.axes;
  return std::cos(a) * row(t, 0) +
         std::sin(a) * (std::cos(turn) * row(t, 1) + std::sin(turn) * row(t, 2));
}

synth::Pose random_pose(std::mt19937_64& rng, double size) { return synth::random_pose(rng, size); }

double random_size(std::mt19937_64& rng) {
  return std::exp(std::uniform_real_distribution<double>(std::log(0.05), std::log(50.0))(rng));
}

}  // namespace cloudshape::positive
