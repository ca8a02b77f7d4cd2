// A ROS 2 sensor_msgs/msg/PointCloud2 as CDR bytes (a recording's message) to and from the plain
// PointCloud2 value that decode_pointcloud2 turns into a cloud.
#include "io/pointcloud2_cdr.hpp"

#include "io/detail/cdr.hpp"

namespace cloudshape::io {

PointCloud2 pointcloud2_from_cdr(std::string_view bytes, const std::string& name, const std::string& place,
                                 const ReadLimits& limits) {
  detail::cdr::Reader in(bytes, name, place);
  PointCloud2 cloud;
  cloud.header.stamp.sec = in.i32("header.stamp.sec");
  cloud.header.stamp.nanosec = in.u32("header.stamp.nanosec");
  cloud.header.frame_id = in.string("header.frame_id");
  cloud.height = in.u32("height");
  cloud.width = in.u32("width");
  // A PointField takes at least 4 (name length) + 4 + 1 + 4 bytes.
  const std::uint32_t fields = in.count("fields", 13);
  cloud.fields.resize(fields);
  for (PointField& f : cloud.fields) {
    f.name = in.string("fields.name");
    f.offset = in.u32("fields.offset");
    f.datatype = in.u8("fields.datatype");
    f.count = in.u32("fields.count");
  }
  cloud.is_bigendian = in.boolean("is_bigendian");
  cloud.point_step = in.u32("point_step");
  cloud.row_step = in.u32("row_step");
  const std::uint32_t size = in.count("data", 1);
  if (size > limits.max_bytes) {
    in.fail("CDR: " + std::to_string(size) + " bytes of point data, more than the limit of " +
            std::to_string(limits.max_bytes));
  }
  const std::string_view data = in.take(size, 1, "data");
  cloud.data.assign(data.begin(), data.end());
  cloud.is_dense = in.boolean("is_dense");
  return cloud;
}

std::string pointcloud2_to_cdr(const PointCloud2& cloud) {
  detail::cdr::Writer out;
  out.u32(static_cast<std::uint32_t>(cloud.header.stamp.sec));
  out.u32(cloud.header.stamp.nanosec);
  out.string(cloud.header.frame_id);
  out.u32(cloud.height);
  out.u32(cloud.width);
  out.u32(static_cast<std::uint32_t>(cloud.fields.size()));
  for (const PointField& f : cloud.fields) {
    out.string(f.name);
    out.u32(f.offset);
    out.u8(f.datatype);
    out.u32(f.count);
  }
  out.u8(cloud.is_bigendian ? 1 : 0);
  out.u32(cloud.point_step);
  out.u32(cloud.row_step);
  out.u32(static_cast<std::uint32_t>(cloud.data.size()));
  out.bytes(cloud.data.data(), cloud.data.size());
  out.u8(cloud.is_dense ? 1 : 0);
  return out.take();
}

}  // namespace cloudshape::io
