#include "synth/triangle_bvh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace cloudshape::synth {

namespace {

constexpr std::uint32_t kLeafSize = 4;

// Slab test: does origin + t * direction pass through the box for some t in [0, t_max]?
bool segment_meets_box(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& origin,
                       const Eigen::Vector3d& inverse_direction, double t_max) {
  double near = 0.0, far = t_max;
  for (int axis = 0; axis < 3; ++axis) {
    double t0 = (box.min()[axis] - origin[axis]) * inverse_direction[axis];
    double t1 = (box.max()[axis] - origin[axis]) * inverse_direction[axis];
    // A direction component of zero gives +-inf (or NaN on the slab's plane; the max/min below
    // then keep the other bound, which is the conservative choice).
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
    if (near > far) return false;
  }
  return true;
}

}  // namespace

TriangleBvh::TriangleBvh(const PointList& vertices, const std::vector<Triangle>& triangles) {
  check_triangle_indices(vertices, triangles);
  std::vector<Eigen::Vector3d> centroids;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Eigen::Vector3d& a = vertices[triangles[t][0]];
    const Eigen::Vector3d ab = vertices[triangles[t][1]] - a, ac = vertices[triangles[t][2]] - a;
    const double area = ab.cross(ac).norm();
    if (!(area > 0.0) || !std::isfinite(area)) continue;
    triangles_.push_back({a, ab, ac});
    centroids.push_back(a + (ab + ac) / 3.0);
  }
  if (triangles_.empty()) return;
  nodes_.reserve(2 * triangles_.size() / kLeafSize + 2);
  build(0, static_cast<std::uint32_t>(triangles_.size()), centroids);
}

// Median split along the widest extent of the centroids; triangles_ and centroids are reordered
// together so each leaf owns a contiguous run.
std::uint32_t TriangleBvh::build(std::uint32_t first, std::uint32_t count,
                                 std::vector<Eigen::Vector3d>& centroids) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Eigen::AlignedBox3d box, centre_box;
  for (std::uint32_t i = first; i < first + count; ++i) {
    const Corners& c = triangles_[i];
    box.extend(c.a).extend(c.a + c.ab).extend(c.a + c.ac);
    centre_box.extend(centroids[i]);
  }
  nodes_[index].box = box;
  if (count <= kLeafSize) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  int axis;
  centre_box.sizes().maxCoeff(&axis);
  std::vector<std::uint32_t> order(count);
  std::iota(order.begin(), order.end(), first);
  const std::uint32_t half = count / 2;
  std::nth_element(order.begin(), order.begin() + half, order.end(),
                   [&](std::uint32_t l, std::uint32_t r) {
                     return centroids[l][axis] < centroids[r][axis];
                   });
  std::vector<Corners> moved_triangles;
  std::vector<Eigen::Vector3d> moved_centroids;
  moved_triangles.reserve(count);
  moved_centroids.reserve(count);
  for (std::uint32_t i : order) {
    moved_triangles.push_back(triangles_[i]);
    moved_centroids.push_back(centroids[i]);
  }
  std::copy(moved_triangles.begin(), moved_triangles.end(), triangles_.begin() + first);
  std::copy(moved_centroids.begin(), moved_centroids.end(), centroids.begin() + first);

  build(first, half, centroids);  // the first child follows its parent directly
  const std::uint32_t second = build(first + half, count - half, centroids);
  nodes_[index].first = second;
  return index;
}

bool TriangleBvh::segment_hits(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                               double t_max) const {
  if (nodes_.empty() || !(t_max > 0.0)) return false;
  const Eigen::Vector3d inverse = direction.cwiseInverse();
  std::array<std::uint32_t, 64> stack;
  std::size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!segment_meets_box(node.box, origin, inverse, t_max)) continue;
    if (node.count == 0) {
      const auto self = static_cast<std::uint32_t>(&node - nodes_.data());
      stack[top++] = self + 1;
      stack[top++] = node.first;
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
      // Moller-Trumbore, with closed edges (u, v >= 0, u + v <= 1).
      const Corners& c = triangles_[i];
      const Eigen::Vector3d p = direction.cross(c.ac);
      const double det = c.ab.dot(p);
      if (det == 0.0) continue;  // the segment runs in the triangle's plane
      const double inv_det = 1.0 / det;
      const Eigen::Vector3d s = origin - c.a;
      const double u = s.dot(p) * inv_det;
      if (u < 0.0 || u > 1.0) continue;
      const Eigen::Vector3d q = s.cross(c.ab);
      const double v = direction.dot(q) * inv_det;
      if (v < 0.0 || u + v > 1.0) continue;
      const double t = c.ac.dot(q) * inv_det;
      if (t > 0.0 && t < t_max) return true;
    }
  }
  return false;
}

}  // namespace cloudshape::synth
