#include "render/view.hpp"

#include <algorithm>
#include <cmath>

namespace cloudshape::render {
namespace {

// Closer than this (in the cloud's unit) a pinhole camera sees nothing.
constexpr double kNear = 1e-6;

double percentile(std::vector<double>& values, double q) {
  const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[static_cast<std::size_t>(k)];
}

}  // namespace

Eigen::Vector3d Camera::toward_viewer(const Eigen::Vector3d& p) const {
  if (perspective) {
    const Eigen::Vector3d d = eye - p;
    if (d.norm() > 0.0) return d.normalized();
  }
  return -rotation.row(2).transpose();
}

std::optional<Eigen::Vector2d> View::image_plane(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d c = camera.to_camera(p);
  if (!camera.perspective) return c.head<2>();
  if (!(c.z() > kNear)) return std::nullopt;
  return Eigen::Vector2d(c.x() / c.z(), c.y() / c.z());
}

std::optional<Eigen::Vector3d> View::pixel(const Eigen::Vector3d& p) const {
  const auto plane = image_plane(p);
  if (!plane) return std::nullopt;
  const Eigen::Vector2d px = offset + scale * *plane;
  return Eigen::Vector3d(px.x(), px.y(), camera.to_camera(p).z());
}

std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> View::segment(
    const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  Eigen::Vector3d pa = a, pb = b;
  if (camera.perspective) {
    const double za = camera.to_camera(a).z(), zb = camera.to_camera(b).z();
    if (za <= kNear && zb <= kNear) return std::nullopt;
    // Cut at a plane just in front of the camera so that both ends project.
    const double cut = 2.0 * kNear;
    if (za < cut) pa = a + (b - a) * ((cut - za) / (zb - za));
    if (zb < cut) pb = b + (a - b) * ((cut - zb) / (za - zb));
  }
  const auto qa = pixel(pa), qb = pixel(pb);
  if (!qa || !qb) return std::nullopt;
  return std::make_pair(Eigen::Vector2d(qa->head<2>()), Eigen::Vector2d(qb->head<2>()));
}

View fit_view(const Camera& camera, const std::vector<Eigen::Vector3d>& points,
              const std::vector<Eigen::Vector3d>& also, const PixelRect& rect, double margin,
              double zoom_out) {
  View view;
  view.camera = camera;
  std::vector<double> xs, ys;
  xs.reserve(points.size());
  ys.reserve(points.size());
  for (const Eigen::Vector3d& p : points) {
    if (const auto q = view.image_plane(p)) {
      xs.push_back(q->x());
      ys.push_back(q->y());
    }
  }
  Eigen::Vector2d lo(-1, -1), hi(1, 1);
  if (!xs.empty()) {
    lo = {percentile(xs, 0.01), percentile(ys, 0.01)};
    hi = {percentile(xs, 0.99), percentile(ys, 0.99)};
  }
  const Eigen::Vector2d mid = 0.5 * (lo + hi), half = 0.5 * zoom_out * (hi - lo);
  lo = mid - half;
  hi = mid + half;
  for (const Eigen::Vector3d& p : also) {
    if (const auto q = view.image_plane(p)) {
      lo = lo.cwiseMin(q->cwiseMax(mid - 2.0 * half));
      hi = hi.cwiseMax(q->cwiseMin(mid + 2.0 * half));
    }
  }
  Eigen::Vector2d size = hi - lo;
  const double largest = std::max(size.x(), size.y());
  const double floor = largest > 0.0 ? 1e-3 * largest : 1.0;  // a flat or single-point cloud
  size = size.cwiseMax(floor);
  const double usable_w = std::max(1.0, rect.width - 2.0 * margin);
  const double usable_h = std::max(1.0, rect.height - 2.0 * margin);
  view.scale = std::min(usable_w / size.x(), usable_h / size.y());
  const Eigen::Vector2d rect_mid(rect.x + 0.5 * rect.width, rect.y + 0.5 * rect.height);
  view.offset = rect_mid - view.scale * 0.5 * (lo + hi);
  return view;
}

}  // namespace cloudshape::render
