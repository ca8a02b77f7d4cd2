#include "render/hidden_lines.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cloudshape::render {
namespace {

constexpr double kPiecePixels = 3.0;
// How far around a piece to look for a point in front: wider than the gaps between splats.
constexpr int kLookAround = 2;
constexpr double kDepthTolerance = 0.03;
constexpr double kSizeTolerance = 0.05;

double wireframe_size(const Wireframe& wireframe) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Polyline& line : wireframe.lines)
    for (const Eigen::Vector3d& p : line.points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  return hi.x() >= lo.x() ? (hi - lo).norm() : 0.0;
}

float nearest_depth_around(const DepthBuffer& depth, const Eigen::Vector2d& px) {
  const int x = static_cast<int>(std::floor(px.x())), y = static_cast<int>(std::floor(px.y()));
  float nearest = depth.at(x, y);
  for (int dy = -kLookAround; dy <= kLookAround; ++dy)
    for (int dx = -kLookAround; dx <= kLookAround; ++dx) nearest = std::min(nearest, depth.at(x + dx, y + dy));
  return nearest;
}

void add_segment(const View& view, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                 const DepthBuffer& depth, double tolerance, std::vector<WirePiece>& out) {
  const auto whole = view.segment(a, b);
  if (!whole) return;
  const int n = std::clamp(static_cast<int>(std::ceil((whole->second - whole->first).norm() / kPiecePixels)), 1, 4000);
  bool joining = false;
  for (int k = 0; k < n; ++k) {
    const auto piece = view.segment(a + (b - a) * (static_cast<double>(k) / n), a + (b - a) * (static_cast<double>(k + 1) / n));
    if (!piece) {
      joining = false;
      continue;
    }
    const auto middle = view.pixel(a + (b - a) * ((k + 0.5) / n));
    const bool hidden = middle && nearest_depth_around(depth, middle->head<2>()) < middle->z() - tolerance;
    if (joining && out.back().hidden == hidden) {
      out.back().to = piece->second;
    } else {
      out.push_back({piece->first, piece->second, hidden});
    }
    joining = true;
  }
}

}  // namespace

std::vector<WirePiece> wire_pieces(const View& view, const Wireframe& wireframe, const DepthBuffer& depth) {
  const double range = depth.far > depth.near ? depth.far - depth.near : 0.0;
  const double tolerance = std::max(kDepthTolerance * range, kSizeTolerance * wireframe_size(wireframe));
  std::vector<WirePiece> out;
  for (const Polyline& line : wireframe.lines) {
    const std::size_t n = line.points.size();
    const std::size_t segments = line.closed ? n : (n > 0 ? n - 1 : 0);
    const double line_tolerance = line.outline ? std::numeric_limits<double>::infinity() : tolerance;
    for (std::size_t k = 0; k < segments; ++k)
      add_segment(view, line.points[k], line.points[(k + 1) % n], depth, line_tolerance, out);
  }
  return out;
}

}  // namespace cloudshape::render
