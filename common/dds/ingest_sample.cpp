// What cloudshape-ingest does with one raw-cloud sample: checks it, then splits and preprocesses it
// exactly as recognize_cloud does, one filtered cloud per object.
#include "dds/ingest_sample.hpp"

#include <algorithm>
#include <chrono>
#include <sstream>

#include "dds/convert.hpp"
#include "dds/raw_cloud_layout.hpp"
#include "pipeline/object_clouds.hpp"

namespace cloudshape::dds {

RawCloudPoints raw_cloud_points(const msg::RawCloud& cloud, const config::InputConfig& limits) {
  const std::vector<double>& xyz = cloud.xyz();
  if (xyz.size() % 3 != 0) {
    throw RawCloudError("xyz holds " + std::to_string(xyz.size()) + " values, not whole x y z triples");
  }
  const std::size_t count = xyz.size() / 3;
  if (count == 0) throw RawCloudError("no points (xyz is empty)");
  const std::size_t bytes = xyz.size() * sizeof(double);
  if (bytes > static_cast<std::size_t>(limits.max_bytes)) {
    throw RawCloudError(std::to_string(bytes) + " bytes of coordinates, more than input.max_bytes " +
                        std::to_string(limits.max_bytes));
  }
  if (count > static_cast<std::size_t>(limits.max_points)) {
    throw RawCloudError(std::to_string(count) + " points, more than input.max_points " +
                        std::to_string(limits.max_points));
  }
  const GridLayout layout = raw_cloud_layout(cloud, count, limits);
  const bool organized = layout.organized();
  RawCloudPoints out;
  out.points.reserve(count);
  if (organized) {
    out.grid.width = layout.width;
    out.grid.height = layout.height;
    out.grid.pixel.reserve(count);
  }
  for (std::size_t i = 0; i < count; ++i) {
    const Point p(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    // Another DDS program may send NaN: such points (and their pixels) are dropped, as the file
    // readers drop them.
    if (p.allFinite()) {
      out.points.push_back(p);
      if (organized) out.grid.pixel.push_back(layout.pixel[i]);
    } else {
      ++out.non_finite_dropped;
    }
  }
  check_usable_points(out, count, limits);
  return out;
}

void check_usable_points(const RawCloudPoints& cloud, std::size_t count, const config::InputConfig& limits) {
  if (cloud.points.empty()) {
    throw RawCloudError("no usable points (all " + std::to_string(count) +
                        " points have NaN or infinite coordinates)");
  }
  const std::size_t far = first_point_beyond(cloud.points, limits.max_coordinate);
  if (far < cloud.points.size()) {
    std::ostringstream text;
    text << "a point at (" << cloud.points[far].transpose() << "), beyond input.max_coordinate "
         << limits.max_coordinate;
    throw RawCloudError(text.str());
  }
}

std::vector<msg::FilteredCloud> ingest_raw_cloud(const msg::RawCloud& in, const config::PipelineConfig& cfg,
                                                 parallel::ThreadPool* pool) {
  return filtered_clouds(in.header(), raw_cloud_points(in, cfg.input), cfg, pool);
}

std::vector<msg::FilteredCloud> filtered_clouds(const msg::CloudHeader& header, const RawCloudPoints& raw,
                                                const config::PipelineConfig& cfg, parallel::ThreadPool* pool) {
  const auto start = std::chrono::steady_clock::now();
  const pipeline::ObjectClouds clouds = pipeline::object_clouds(raw.points, raw.grid, cfg.preprocess, cfg.segment, pool);
  const std::vector<pipeline::ObjectCloud>& objects = clouds.objects;
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::vector<msg::FilteredCloud> out;
  // No object at all still makes one message (object_count 0): one result per cloud.
  const std::size_t count = objects.size();
  for (std::size_t i = 0; i < std::max<std::size_t>(count, 1); ++i) {
    msg::FilteredCloud o;
    o.header(header);
    o.header().object_index(static_cast<std::uint32_t>(i));
    o.header().object_count(static_cast<std::uint32_t>(count));
    o.header().timings().preprocess_ms(ms);
    o.cloud(to_msg(count == 0 ? PointList{} : objects[i].points, clouds.scene, raw.points.size()));
    // An object found among a scene's structure was gridded at its own resolution.
    if (count != 0) {
      o.cloud().resolution(objects[i].resolution);
      o.cloud().scan_lines(objects[i].scan_lines);
      o.cloud().returns_about(to_xyz(objects[i].returns_about));
    }
    set_viewpoint(o.cloud(), clouds.viewpoint);
    out.push_back(std::move(o));
  }
  return out;
}

msg::FilteredCloud refused_raw_cloud(const msg::RawCloud& in, const std::string& stage, const std::string& text) {
  return refused_cloud(in.header(), stage, text);
}

msg::FilteredCloud refused_cloud(const msg::CloudHeader& header, const std::string& stage, const std::string& text) {
  msg::FilteredCloud out;
  out.header(header);
  out.header().object_index(0);
  out.header().object_count(1);
  out.header().error(true);
  out.header().error_stage(stage);
  out.header().error_text(text);
  return out;
}

}  // namespace cloudshape::dds
