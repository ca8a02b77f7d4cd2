#include "render/picture_plan.hpp"

#include <algorithm>
#include <cmath>

#include "render/cameras.hpp"

namespace cloudshape::render {
namespace {

constexpr double kHeaderHeight = 36.0;
constexpr std::size_t kMaxLegendRows = 6;
constexpr double kMargin = 36.0;
constexpr double kObliqueAzimuthDeg = 40.0;
constexpr double kObliqueElevationDeg = 30.0;
// The first view frames the objects with some of their surroundings, the oblique one closer.
constexpr double kFirstZoomOut = 1.3;
constexpr double kObliqueZoomOut = 1.1;
// Enough points to place a camera and frame a view; every point is still drawn.
constexpr std::size_t kFramingSample = 40000;

std::vector<Eigen::Vector3d> every_kth(const PointList& points, const std::vector<std::uint32_t>& indices) {
  const std::size_t n = indices.empty() ? points.size() : indices.size();
  const std::size_t step = std::max<std::size_t>(1, n / kFramingSample);
  std::vector<Eigen::Vector3d> out;
  out.reserve(n / step + 1);
  for (std::size_t k = 0; k < n; k += step) out.push_back(points[indices.empty() ? k : indices[k]]);
  return out;
}

// The objects' points (the background left out), or every point when no object has any.
std::vector<std::uint32_t> object_points(const pipeline::RecognitionResult& result, std::size_t n) {
  std::vector<std::uint32_t> out;
  for (const pipeline::ObjectResult& o : result.objects)
    for (std::uint32_t i : o.point_indices)
      if (i < n) out.push_back(i);
  std::sort(out.begin(), out.end());
  return out;
}

Eigen::Vector3d median(std::vector<Eigen::Vector3d> points) {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  if (points.empty()) return out;
  const auto mid = static_cast<std::ptrdiff_t>(points.size() / 2);
  for (int axis = 0; axis < 3; ++axis) {
    std::nth_element(points.begin(), points.begin() + mid, points.end(),
                     [axis](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a[axis] < b[axis]; });
    out[axis] = points[static_cast<std::size_t>(mid)][axis];
  }
  return out;
}

// Where the sensor most likely was, for a cloud with no sensor pose: a sensor sees the near side
// of a solid, so the seen points sit between it and the solid's centre; with no solid to tell
// (or no clear offset), the origin, where a sensor's own frame puts it.
Eigen::Vector3d viewer_side(const PointList& points, const pipeline::RecognitionResult& result,
                            const std::vector<Eigen::Vector3d>& sample) {
  Eigen::Vector3d toward = Eigen::Vector3d::Zero();
  for (const pipeline::ObjectResult& o : result.objects) {
    if (o.shape == "unknown" || o.point_indices.empty()) continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    std::size_t n = 0;
    for (std::uint32_t i : o.point_indices)
      if (i < points.size()) {
        mean += points[i];
        ++n;
      }
    if (n > 0) toward += mean / static_cast<double>(n) - o.center;
  }
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : sample) centroid += p / static_cast<double>(sample.size());
  double spread = 0.0;
  for (const Eigen::Vector3d& p : sample) spread += (p - centroid).squaredNorm() / static_cast<double>(sample.size());
  spread = std::sqrt(spread);
  if (!(toward.norm() > 0.02 * spread)) return Eigen::Vector3d::Zero();
  return centroid + 10.0 * spread * toward.normalized();
}

Panel make_panel(std::string caption, const Camera& camera, const PixelRect& rect,
                 const std::vector<Eigen::Vector3d>& frame_points, double zoom_out,
                 const pipeline::RecognitionResult& result) {
  Panel panel;
  panel.caption = std::move(caption);
  panel.rect = rect;
  std::vector<Eigen::Vector3d> corners;
  for (const pipeline::ObjectResult& o : result.objects) {
    panel.wireframes.push_back(solid_wireframe(o, camera.toward_viewer(o.center)));
    for (const Polyline& line : panel.wireframes.back().lines)
      corners.insert(corners.end(), line.points.begin(), line.points.end());
  }
  panel.view = fit_view(camera, frame_points, corners, rect, kMargin, zoom_out);
  return panel;
}

}  // namespace

PicturePlan plan_picture(const PointList& points, const GridLayout& grid,
                         const pipeline::RecognitionResult& result, const RenderOptions& options) {
  PicturePlan plan;
  plan.width = options.width;
  plan.height = options.height;
  plan.header = {0.0, 0.0, static_cast<double>(options.width), kHeaderHeight};
  const std::size_t n = result.objects.size();
  plan.legend_rows = std::min(kMaxLegendRows, (n + plan.legend_columns - 1) / plan.legend_columns);
  const double legend_height = plan.legend_rows > 0 ? plan.legend_rows * kLegendRowHeight + 8.0 : 0.0;
  plan.legend = {0.0, kHeaderHeight, static_cast<double>(options.width), legend_height};
  const double top = kHeaderHeight + legend_height;
  const double half = 0.5 * options.width;
  const PixelRect left{0.0, top, half, options.height - top};
  const PixelRect right{half, top, options.width - half, options.height - top};

  const std::vector<Eigen::Vector3d> all = every_kth(points, {});
  std::vector<Eigen::Vector3d> objects = every_kth(points, object_points(result, points.size()));
  if (objects.empty()) objects = all;

  const bool organized = grid.organized();
  const Camera first = organized ? sensor_camera() : principal_axes_camera(all, viewer_side(points, result, all));
  plan.panels.push_back(make_panel(organized ? "sensor view: camera at the origin, looking along +z"
                                             : "principal-axes view: along the cloud's thinnest axis",
                                   first, left, objects, kFirstZoomOut, result));
  const Camera oblique = oblique_camera(first, median(objects), kObliqueAzimuthDeg, kObliqueElevationDeg);
  plan.panels.push_back(make_panel("oblique view: 40 degrees right, 30 degrees above", oblique,
                                   right, objects, kObliqueZoomOut, result));
  return plan;
}

}  // namespace cloudshape::render
