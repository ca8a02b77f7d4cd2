// Clouds, timings and final results across the wire.
#include <array>
#include <stdexcept>

#include "dds/convert.hpp"

namespace cloudshape::dds {

std::vector<double> to_xyz(const PointList& points) {
  std::vector<double> xyz(points.size() * 3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    xyz[3 * i] = points[i].x();
    xyz[3 * i + 1] = points[i].y();
    xyz[3 * i + 2] = points[i].z();
  }
  return xyz;
}

PointList from_xyz(const std::vector<double>& xyz) {
  if (xyz.size() % 3 != 0) {
    throw std::invalid_argument("xyz holds " + std::to_string(xyz.size()) +
                                " values, not a multiple of 3");
  }
  // reserve + emplace: one pass over the (up to 48 MB) buffer instead of zero-fill then copy.
  PointList points;
  points.reserve(xyz.size() / 3);
  for (std::size_t i = 0; i < xyz.size(); i += 3) points.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
  return points;
}

msg::RawCloud to_raw_cloud(const PointList& points, const GridLayout& grid) {
  msg::RawCloud m;
  m.xyz(to_xyz(points));
  if (grid.organized()) {
    m.width(static_cast<std::uint32_t>(grid.width));
    m.height(static_cast<std::uint32_t>(grid.height));
    m.pixel(grid.pixel);
  }
  return m;
}

msg::CloudData to_msg(const pipeline::PreprocessedCloud& cloud, std::size_t points_in) {
  return to_msg(cloud.points, cloud, points_in);
}

msg::CloudData to_msg(const PointList& object, const pipeline::PreprocessedCloud& cloud,
                      std::size_t points_in) {
  msg::CloudData m;
  m.points_in(points_in);
  m.points_used(cloud.points.size());
  m.xyz(to_xyz(object));
  m.resolution(cloud.resolution);
  m.voxel_size(cloud.voxel_size);
  m.outliers_removed(cloud.outliers_removed);
  return m;
}

void set_viewpoint(msg::CloudData& m, const std::optional<Point>& viewpoint) {
  m.viewpoint_known(viewpoint.has_value());
  m.viewpoint(viewpoint ? std::array<double, 3>{viewpoint->x(), viewpoint->y(), viewpoint->z()}
                        : std::array<double, 3>{0.0, 0.0, 0.0});
}

std::optional<Point> viewpoint_of(const msg::CloudData& m) {
  if (!m.viewpoint_known()) return std::nullopt;
  return Point(m.viewpoint()[0], m.viewpoint()[1], m.viewpoint()[2]);
}

pipeline::PreprocessedCloud from_msg(const msg::CloudData& m) {
  pipeline::PreprocessedCloud cloud;
  cloud.points = from_xyz(m.xyz());
  cloud.resolution = m.resolution();
  cloud.voxel_size = m.voxel_size();
  cloud.outliers_removed = m.outliers_removed();
  return cloud;
}

msg::StageTimings to_msg(const pipeline::StageTimings& t) {
  msg::StageTimings m;
  m.preprocess_ms(t.preprocess_ms);
  m.planes_ms(t.planes_ms);
  m.keypoints_ms(t.keypoints_ms);
  m.classify_ms(t.classify_ms);
  m.solve_ms(t.solve_ms);
  return m;
}

pipeline::StageTimings from_msg(const msg::StageTimings& m) {
  pipeline::StageTimings t;
  t.preprocess_ms = m.preprocess_ms();
  t.planes_ms = m.planes_ms();
  t.keypoints_ms = m.keypoints_ms();
  t.classify_ms = m.classify_ms();
  t.solve_ms = m.solve_ms();
  t.total_ms = t.preprocess_ms + t.planes_ms + t.keypoints_ms + t.classify_ms + t.solve_ms;
  return t;
}

msg::ObjectResult to_msg(const pipeline::ObjectResult& o) {
  msg::ObjectResult m;
  m.shape(o.shape);
  m.confidence(o.confidence);
  for (const auto& [name, value] : o.dimensions) {
    msg::Dimension d;
    d.name(name);
    d.value(value);
    m.dimensions().push_back(d);
  }
  m.center({o.center.x(), o.center.y(), o.center.z()});
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m.axes()[3 * r + c] = o.axes(r, c);
  }
  m.partial(o.partial);
  m.keypoints().corner(o.keypoints.corner);
  m.keypoints().edge(o.keypoints.edge);
  m.keypoints().border(o.keypoints.border);
  m.reason(o.reason);
  for (int k = 0; k < 3; ++k) {
    m.extent().center()[k] = o.extent.center[k];
    m.extent().size()[k] = o.extent.size[k];
    for (int c = 0; c < 3; ++c) m.extent().axes()[3 * k + c] = o.extent.axes(k, c);
  }
  for (const Eigen::Vector2d& q : o.polygon) {
    m.polygon().push_back(q.x());
    m.polygon().push_back(q.y());
  }
  for (const Eigen::Vector3d& v : o.vertices)
    for (int k = 0; k < 3; ++k) m.vertices().push_back(v[k]);
  m.regular(o.regular);
  return m;
}

pipeline::ObjectResult from_msg(const msg::ObjectResult& m) {
  pipeline::ObjectResult o;
  o.shape = m.shape();
  o.confidence = m.confidence();
  for (const msg::Dimension& d : m.dimensions()) o.dimensions.emplace_back(d.name(), d.value());
  o.center = Eigen::Vector3d(m.center()[0], m.center()[1], m.center()[2]);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) o.axes(r, c) = m.axes()[3 * r + c];
  }
  o.partial = m.partial();
  o.keypoints.corner = m.keypoints().corner();
  o.keypoints.edge = m.keypoints().edge();
  o.keypoints.border = m.keypoints().border();
  o.reason = m.reason();
  for (int k = 0; k < 3; ++k) {
    o.extent.center[k] = m.extent().center()[k];
    o.extent.size[k] = m.extent().size()[k];
    for (int c = 0; c < 3; ++c) o.extent.axes(k, c) = m.extent().axes()[3 * k + c];
  }
  for (std::size_t i = 0; i + 1 < m.polygon().size(); i += 2)
    o.polygon.emplace_back(m.polygon()[i], m.polygon()[i + 1]);
  for (std::size_t i = 0; i + 2 < m.vertices().size(); i += 3)
    o.vertices.emplace_back(m.vertices()[i], m.vertices()[i + 1], m.vertices()[i + 2]);
  o.regular = m.regular();
  return o;
}

pipeline::RecognitionResult to_recognition_result(const msg::ShapeResult& m) {
  pipeline::RecognitionResult r;
  r.source = m.header().source();
  r.points_in = m.points_in();
  r.points_used = m.points_used();
  r.resolution = m.resolution();
  for (const msg::ObjectResult& o : m.objects()) r.objects.push_back(from_msg(o));
  r.timings = from_msg(m.header().timings());
  return r;
}

pipeline::RecognitionResult to_recognition_result(const std::vector<msg::ShapeResult>& objects) {
  if (objects.empty()) return {};
  pipeline::RecognitionResult r = to_recognition_result(objects.front());
  for (std::size_t i = 1; i < objects.size(); ++i) {
    const pipeline::RecognitionResult more = to_recognition_result(objects[i]);
    r.objects.insert(r.objects.end(), more.objects.begin(), more.objects.end());
    r.timings.planes_ms += more.timings.planes_ms;
    r.timings.keypoints_ms += more.timings.keypoints_ms;
    r.timings.classify_ms += more.timings.classify_ms;
    r.timings.solve_ms += more.timings.solve_ms;
  }
  const pipeline::StageTimings& t = r.timings;
  r.timings.total_ms = t.preprocess_ms + t.planes_ms + t.keypoints_ms + t.classify_ms + t.solve_ms;
  return r;
}

}  // namespace cloudshape::dds
