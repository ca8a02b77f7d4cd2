// Decodes a sensor_msgs/PointCloud2 into finite x y z points (grid kept for organized clouds).
// The layout is checked completely before any point is read: a sender's layout is input too.
#include "io/pointcloud2.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <optional>

#include "io/read_error.hpp"

namespace cloudshape::io {
namespace {

constexpr std::uint64_t kPixelIndexLimit = std::uint64_t{std::numeric_limits<std::uint32_t>::max()} + 1;

std::size_t datatype_size(std::uint8_t datatype) {
  switch (static_cast<PointFieldType>(datatype)) {
    case PointFieldType::int8:
    case PointFieldType::uint8: return 1;
    case PointFieldType::int16:
    case PointFieldType::uint16: return 2;
    case PointFieldType::int32:
    case PointFieldType::uint32:
    case PointFieldType::float32: return 4;
    case PointFieldType::float64: return 8;
  }
  return 0;
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

std::string field_list(const std::vector<PointField>& fields) {
  if (fields.empty()) return "none";
  std::string out;
  for (const PointField& f : fields) out += (out.empty() ? "" : ", ") + f.name;
  return out;
}

// Where one coordinate sits in a point and how to load it.
struct Coordinate {
  std::uint32_t offset = 0;
  bool f64 = false;
};

// Every field has a known type and fits inside point_step; x, y and z exist once each as one
// FLOAT32 or FLOAT64.
std::array<Coordinate, 3> check_fields(const PointCloud2& cloud, const std::string& name) {
  static const std::array<const char*, 3> kAxes = {"x", "y", "z"};
  std::array<std::optional<Coordinate>, 3> found;
  for (const PointField& f : cloud.fields) {
    const std::string place = "field " + quoted(f.name);
    const std::size_t size = datatype_size(f.datatype);
    if (size == 0) {
      throw ReadError(name, place, "unknown datatype " + std::to_string(f.datatype) +
                                       " (sensor_msgs/PointField defines 1..8)");
    }
    const std::uint64_t end = std::uint64_t{f.offset} + std::uint64_t{f.count} * size;
    if (end > cloud.point_step) {
      throw ReadError(name, place,
                      "offset " + std::to_string(f.offset) + " + " + std::to_string(f.count) + " x " +
                          point_field_type_name(f.datatype) + " ends at byte " + std::to_string(end) +
                          ", past point_step " + std::to_string(cloud.point_step));
    }
    const auto axis = std::find(kAxes.begin(), kAxes.end(), f.name);
    if (axis == kAxes.end()) continue;
    auto& slot = found[static_cast<std::size_t>(axis - kAxes.begin())];
    if (slot) throw ReadError(name, place, "two fields have this name");
    const auto type = static_cast<PointFieldType>(f.datatype);
    if (type != PointFieldType::float32 && type != PointFieldType::float64) {
      throw ReadError(name, place, "is " + point_field_type_name(f.datatype) +
                                       "; x, y and z must be FLOAT32 or FLOAT64");
    }
    if (f.count != 1) {
      throw ReadError(name, place, "count is " + std::to_string(f.count) + "; x, y and z must have count 1");
    }
    slot = Coordinate{f.offset, type == PointFieldType::float64};
  }
  std::array<Coordinate, 3> out;
  for (std::size_t a = 0; a < 3; ++a) {
    if (!found[a]) {
      throw ReadError(name, "fields", std::string("no field named '") + kAxes[a] +
                                          "' (fields: " + field_list(cloud.fields) + ")");
    }
    out[a] = *found[a];
  }
  return out;
}

// point_step, row_step, width * height and the size of data agree, within the limits.
void check_extent(const PointCloud2& cloud, const std::string& name, const ReadLimits& limits) {
  const std::uint64_t points = std::uint64_t{cloud.width} * cloud.height;
  if (points > limits.max_points) {
    throw ReadError(name, "width * height",
                    std::to_string(cloud.width) + " x " + std::to_string(cloud.height) + " = " +
                        std::to_string(points) + " points, more than the limit of " +
                        std::to_string(limits.max_points));
  }
  if (cloud.height > 1 && points > kPixelIndexLimit) {
    throw ReadError(name, "width * height", std::to_string(points) +
                                                " pixels: more than a 32-bit pixel index addresses");
  }
  if (cloud.data.size() > limits.max_bytes) {
    throw ReadError(name, "data", std::to_string(cloud.data.size()) + " bytes, more than the limit of " +
                                      std::to_string(limits.max_bytes));
  }
  const std::uint64_t row_bytes = std::uint64_t{cloud.width} * cloud.point_step;
  if (row_bytes > cloud.row_step) {
    throw ReadError(name, "row_step",
                    std::to_string(cloud.row_step) + " is less than width * point_step = " +
                        std::to_string(cloud.width) + " x " + std::to_string(cloud.point_step) + " = " +
                        std::to_string(row_bytes));
  }
  const std::uint64_t expected = std::uint64_t{cloud.row_step} * cloud.height;
  if (cloud.data.size() != expected) {
    throw ReadError(name, "data",
                    std::to_string(cloud.data.size()) + " bytes, " +
                        (cloud.data.size() < expected ? "fewer" : "more") + " than row_step * height = " +
                        std::to_string(cloud.row_step) + " x " + std::to_string(cloud.height) + " = " +
                        std::to_string(expected) + " (width x height = " + std::to_string(cloud.width) +
                        " x " + std::to_string(cloud.height) + ")");
  }
}

template <typename T>
T load(const std::uint8_t* p, bool swap) {
  std::array<std::uint8_t, sizeof(T)> bytes;
  std::memcpy(bytes.data(), p, sizeof(T));
  if (swap) std::reverse(bytes.begin(), bytes.end());
  T value;
  std::memcpy(&value, bytes.data(), sizeof(T));
  return value;
}

double load_coordinate(const std::uint8_t* point, const Coordinate& c, bool swap) {
  const std::uint8_t* p = point + c.offset;
  return c.f64 ? load<double>(p, swap) : static_cast<double>(load<float>(p, swap));
}

// The points of every row and column, `load` reading one (a Point), the non-finite ones dropped.
template <class Load>
void decode_points(const PointCloud2& cloud, bool organized, const Load& load, CloudFile& out) {
  for (std::size_t row = 0; row < cloud.height; ++row) {
    const std::uint8_t* row_start = cloud.data.data() + row * cloud.row_step;
    for (std::size_t column = 0; column < cloud.width; ++column) {
      const Point p = load(row_start + column * cloud.point_step);
      if (!p.allFinite()) {
        ++out.non_finite_dropped;
        continue;
      }
      out.points.push_back(p);
      if (organized) out.grid.pixel.push_back(static_cast<std::uint32_t>(row * cloud.width + column));
    }
  }
}

template <typename T>
T load_native(const std::uint8_t* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return value;
}

}  // namespace

std::string point_field_type_name(std::uint8_t datatype) {
  switch (static_cast<PointFieldType>(datatype)) {
    case PointFieldType::int8: return "INT8";
    case PointFieldType::uint8: return "UINT8";
    case PointFieldType::int16: return "INT16";
    case PointFieldType::uint16: return "UINT16";
    case PointFieldType::int32: return "INT32";
    case PointFieldType::uint32: return "UINT32";
    case PointFieldType::float32: return "FLOAT32";
    case PointFieldType::float64: return "FLOAT64";
  }
  return "datatype " + std::to_string(datatype);
}

CloudFile decode_pointcloud2(const PointCloud2& cloud, const std::string& name, const ReadLimits& limits) {
  const std::array<Coordinate, 3> xyz = check_fields(cloud, name);
  check_extent(cloud, name, limits);
  static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "PointCloud2 decoding assumes a little-endian host");
  const bool swap = cloud.is_bigendian;
  const bool organized = cloud.height > 1;
  const std::size_t count = std::size_t{cloud.width} * cloud.height;

  CloudFile out;
  out.format = "ros2-pointcloud2";
  // Width 0 and a height of billions is a valid empty cloud, not billions of empty rows.
  if (count == 0) return out;
  out.points.reserve(count);
  if (organized) {
    out.grid.width = cloud.width;
    out.grid.height = cloud.height;
    out.grid.pixel.reserve(count);
  }
  // The usual layouts (host byte order, x y z of one type) in a loop of their own: the same
  // values as the general one, without its per-coordinate choices.
  const bool one_type = xyz[0].f64 == xyz[1].f64 && xyz[1].f64 == xyz[2].f64;
  const std::uint32_t ox = xyz[0].offset, oy = xyz[1].offset, oz = xyz[2].offset;
  if (!swap && one_type && !xyz[0].f64) {
    decode_points(cloud, organized, [&](const std::uint8_t* q) {
      return Point(static_cast<double>(load_native<float>(q + ox)), static_cast<double>(load_native<float>(q + oy)),
                   static_cast<double>(load_native<float>(q + oz)));
    }, out);
  } else if (!swap && one_type) {
    decode_points(cloud, organized, [&](const std::uint8_t* q) {
      return Point(load_native<double>(q + ox), load_native<double>(q + oy), load_native<double>(q + oz));
    }, out);
  } else {
    decode_points(cloud, organized, [&](const std::uint8_t* q) {
      return Point(load_coordinate(q, xyz[0], swap), load_coordinate(q, xyz[1], swap), load_coordinate(q, xyz[2], swap));
    }, out);
  }
  return out;
}

}  // namespace cloudshape::io
