#include "synth/visibility.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <unordered_map>

namespace cloudshape::synth {

namespace {

constexpr int kIndexBits = 29;  // per cube-face coordinate; 3 + 2*29 bits fit in a key
constexpr double kMinBinAngle = 4.0 / (1 << (kIndexBits - 1));
constexpr double kMaxStepBins = 3.0;

// A frame whose third row points from the camera to the cloud's centroid.
Eigen::Matrix3d view_frame(const PointList& points, const Eigen::Vector3d& camera) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  Eigen::Vector3d z = centroid - camera;
  if (z.norm() < 1e-300) return Eigen::Matrix3d::Identity();
  z.normalize();
  const Eigen::Vector3d helper =
      std::abs(z.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d x = helper.cross(z).normalized();
  Eigen::Matrix3d frame;
  frame.row(0) = x;
  frame.row(1) = z.cross(x);
  frame.row(2) = z;
  return frame;
}

std::uint64_t bin_key(const Eigen::Vector3d& dir, double bin_angle) {
  int face_axis;
  dir.cwiseAbs().maxCoeff(&face_axis);
  const double major = dir[face_axis];
  const int face = 2 * face_axis + (major < 0.0 ? 1 : 0);
  const double inv = 1.0 / std::abs(major);
  const double u = dir[(face_axis + 1) % 3] * inv;
  const double v = dir[(face_axis + 2) % 3] * inv;
  const auto index = [bin_angle](double c) {
    return static_cast<std::uint64_t>(
        std::clamp(std::floor((c + 1.0) / bin_angle), 0.0, double((1ull << kIndexBits) - 1)));
  };
  return (static_cast<std::uint64_t>(face) << (2 * kIndexBits)) | (index(u) << kIndexBits) |
         index(v);
}

}  // namespace

PointList visible_from(const PointList& points, const Eigen::Vector3d& camera, double resolution,
                       double base_tolerance, double slope_tolerance) {
  if (!(resolution > 0.0) || !std::isfinite(resolution))
    throw std::invalid_argument("visibility resolution must be positive and finite");
  if (points.empty()) return {};

  const Eigen::Matrix3d frame = view_frame(points, camera);
  std::vector<double> distance(points.size());
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points.size(); ++i) {
    distance[i] = (points[i] - camera).norm();
    if (distance[i] > 0.0) nearest = std::min(nearest, distance[i]);
  }
  if (!std::isfinite(nearest)) return {};
  const double bin_angle = std::max(resolution / nearest, kMinBinAngle);

  std::vector<std::uint64_t> keys(points.size());
  std::unordered_map<std::uint64_t, double> front;
  front.reserve(points.size() / 4 + 16);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (distance[i] <= 0.0) continue;
    keys[i] = bin_key(frame * (points[i] - camera), bin_angle);
    auto [it, inserted] = front.try_emplace(keys[i], distance[i]);
    if (!inserted) it->second = std::min(it->second, distance[i]);
  }

  // Depth step of the front surface from a bin to its neighbours along one grid direction.
  // The smaller one-sided step is taken so that a depth jump at a silhouette on one side
  // does not pass for a steep surface.
  // Capped at kMaxStepBins bin widths (a ~72 degree incidence): a bin whose front surface was
  // missed by the sampling sees big jumps on both sides, and without the cap that hole would
  // wave through everything behind it.
  const auto step = [&front, bin_angle](std::uint64_t key, double depth, std::uint64_t stride) {
    const double bin_width = bin_angle * depth;
    double best = std::numeric_limits<double>::infinity();
    const std::uint64_t index = (key / stride) & ((1ull << kIndexBits) - 1);
    if (index > 0)
      if (auto it = front.find(key - stride); it != front.end())
        best = std::min(best, std::abs(it->second - depth));
    if (index + 1 < (1ull << kIndexBits))
      if (auto it = front.find(key + stride); it != front.end())
        best = std::min(best, std::abs(it->second - depth));
    return std::isfinite(best) ? std::min(best, kMaxStepBins * bin_width) : 0.0;
  };

  std::unordered_map<std::uint64_t, double> tolerance;
  tolerance.reserve(front.size());
  PointList visible;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (distance[i] <= 0.0) continue;
    const double depth = front.at(keys[i]);
    auto [it, inserted] = tolerance.try_emplace(keys[i], 0.0);
    if (inserted)
      it->second =
          base_tolerance * bin_angle * depth +
          slope_tolerance * (step(keys[i], depth, 1) + step(keys[i], depth, 1ull << kIndexBits));
    if (distance[i] <= depth + it->second) visible.push_back(points[i]);
  }
  return visible;
}

double visibility_resolution(double area, std::size_t n) {
  return 3.0 * std::sqrt(area / static_cast<double>(std::max<std::size_t>(n, 1)));
}

PointList sample_visible(const std::function<PointList(std::size_t)>& sample, double area,
                         std::size_t n, const Eigen::Vector3d& camera, std::mt19937_64& rng) {
  const auto z_buffer = [&](const PointList& points) {
    return visible_from(points, camera, visibility_resolution(area, points.size()));
  };
  return sample_visible(sample, z_buffer, n, rng);
}

PointList sample_visible(const std::function<PointList(std::size_t)>& sample,
                         const std::function<PointList(const PointList&)>& keep_visible,
                         std::size_t n, std::mt19937_64& rng) {
  if (n == 0) return {};
  // Each pass estimates the visible fraction and oversamples by its inverse plus a margin;
  // the cap keeps a nearly invisible surface from exhausting memory.
  const double max_samples = 50.0 * static_cast<double>(n);
  std::size_t m = n;
  PointList visible;
  for (int pass = 0; pass < 4; ++pass) {
    visible = keep_visible(sample(m));
    if (visible.size() >= n || visible.empty() || static_cast<double>(m) >= max_samples) break;
    const double fraction = static_cast<double>(visible.size()) / static_cast<double>(m);
    m = static_cast<std::size_t>(
        std::min(max_samples, std::ceil(1.15 * static_cast<double>(n) / fraction)));
  }
  if (visible.size() <= n) return visible;
  // Partial Fisher-Yates: the first n entries become a uniform random subset.
  for (std::size_t i = 0; i < n; ++i) {
    std::uniform_int_distribution<std::size_t> pick(i, visible.size() - 1);
    std::swap(visible[i], visible[pick(rng)]);
  }
  visible.resize(n);
  return visible;
}

}  // namespace cloudshape::synth
