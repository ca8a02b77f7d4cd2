// Reads PCD point clouds (DATA ascii, binary or binary_compressed) into x/y/z points.
// x, y and z at any field position; non-finite points dropped and counted, pixels and labels kept.
#include "io/pcd_reader.hpp"

#include <lzf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "io/detail/binary_scalar.hpp"
#include "io/detail/input.hpp"
#include "io/detail/parse_number.hpp"
#include "io/detail/pcd_header.hpp"
#include "io/detail/text_lines.hpp"
#include "io/read_error.hpp"

namespace cloudshape::io {
namespace {

using detail::at_byte;
using detail::at_line;
using detail::PcdHeader;
using detail::Scalar;

// LZF's densest code is a 3-byte back reference that expands to 264 bytes; a block
// claiming more than that ratio is corrupt, and is rejected before its buffer is allocated.
constexpr std::uint64_t kMaxLzfRatio = 88;

// Keeps the finite points with, for an organized cloud, the pixel each came from, and the
// ground-truth label of each when the file has a label field.
class PointSink {
 public:
  PointSink(const PcdHeader& h, CloudFile& out) : out_(out), organized_(h.height > 1), labelled_(h.label) {
    if (organized_) {
      out_.grid.width = h.width;
      out_.grid.height = h.height;
    }
  }

  void reserve(std::size_t n) {
    out_.points.reserve(n);
    if (organized_) out_.grid.pixel.reserve(n);
    if (labelled_) out_.labels.reserve(n);
  }

  // `index` is the point's position in the file; `label` is ignored without a label field.
  void add(std::size_t index, double x, double y, double z, double label) {
    if (!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z))) {
      ++out_.non_finite_dropped;
      return;
    }
    out_.points.emplace_back(x, y, z);
    if (organized_) out_.grid.pixel.push_back(static_cast<std::uint32_t>(index));
    if (labelled_) out_.labels.push_back(as_label(label));
  }

  // The binary layouts: room for all `n` points, each finite one written in place by put (no
  // capacity test per point), and the room cut to the ones kept by finish.
  void make_room(std::size_t n) {
    out_.points.resize(n);
    if (organized_) out_.grid.pixel.resize(n);
    if (labelled_) out_.labels.resize(n);
  }
  // As add, after make_room; `label` is called for the label of a point kept in a labelled cloud.
  template <class Label>
  void put(std::size_t index, double x, double y, double z, const Label& label) {
    if (!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z))) {
      ++out_.non_finite_dropped;
      return;
    }
    out_.points[kept_] = Point(x, y, z);
    if (organized_) out_.grid.pixel[kept_] = static_cast<std::uint32_t>(index);
    if (labelled_) out_.labels[kept_] = as_label(label());
    ++kept_;
  }
  void finish() {
    out_.points.resize(kept_);
    if (organized_) out_.grid.pixel.resize(kept_);
    if (labelled_) out_.labels.resize(kept_);
  }

 private:
  static std::uint32_t as_label(double v) {
    return std::isfinite(v) && v >= 0.0 && v <= 4294967295.0 ? static_cast<std::uint32_t>(v) : 0;
  }

  CloudFile& out_;
  bool organized_;
  bool labelled_;
  std::size_t kept_ = 0;  // points put so far
};

void read_ascii(std::string_view data, const std::string& name, const PcdHeader& h, CloudFile& out) {
  PointSink sink(h, out);
  // Every value needs at least one character and one separator, which bounds the
  // reservation by the bytes actually present rather than by the declared count.
  const std::size_t present = (data.size() - h.data_offset) / (2 * h.values_per_point) + 1;
  sink.reserve(std::min(h.points, present));

  detail::LineCursor lines(data, h.data_offset, h.data_line);
  std::string_view line;
  std::size_t rows = 0;
  while (lines.next(line)) {
    if (detail::is_blank(line)) continue;
    const std::size_t line_number = lines.line_number();
    const auto place = [line_number] { return at_line(line_number); };  // only named in an error
    if (rows == h.points) {
      throw ReadError(name, place(), "header/data count mismatch: more data rows than the " +
                                       std::to_string(h.points) + " POINTS declared");
    }
    detail::TokenCursor tokens(line);
    double xyz[3] = {0.0, 0.0, 0.0};
    double label = 0.0;
    std::size_t seen = 0;
    for (std::size_t f = 0; f < h.fields.size(); ++f) {
      const int axis = f == h.xyz[0] ? 0 : f == h.xyz[1] ? 1 : f == h.xyz[2] ? 2 : -1;
      for (std::size_t k = 0; k < h.fields[f].count; ++k, ++seen) {
        std::string_view token;
        if (!tokens.next(token)) {
          throw ReadError(name, place(), "too few values: expected " + std::to_string(h.values_per_point) +
                                           ", found " + std::to_string(seen));
        }
        double value = 0.0;
        if (!detail::parse_double(token, value)) {
          throw ReadError(name, place(), "non-numeric value " + detail::quoted(token) + " in field " +
                                           detail::quoted(h.fields[f].name));
        }
        if (axis >= 0) xyz[axis] = detail::as_declared(value, h.fields[f].type);
        if (h.label && f == *h.label) label = value;
      }
    }
    if (!tokens.at_end()) {
      throw ReadError(name, place(), "too many values: expected " + std::to_string(h.values_per_point));
    }
    sink.add(rows, xyz[0], xyz[1], xyz[2], label);
    ++rows;
  }
  if (rows < h.points) {
    throw ReadError(name, at_line(lines.next_line_number()),
                    "header/data count mismatch: POINTS declares " + std::to_string(h.points) +
                        ", found " + std::to_string(rows) + " data rows");
  }
}

// Where one field's values start and how far apart they lie: the record size for the
// interleaved binary layout, the scalar size for the per-field compressed layout.
struct FieldColumn {
  const unsigned char* start = nullptr;
  std::size_t stride = 0;
  Scalar type = Scalar::f32;

  double at(std::size_t i) const { return detail::load_scalar(start + i * stride, type); }
};

void extract_points(const FieldColumn (&xyz)[3], const FieldColumn* label, const PcdHeader& h, CloudFile& out) {
  PointSink sink(h, out);
  sink.make_room(h.points);
  const auto label_of = [&](std::size_t i) { return [label, i] { return label ? label->at(i) : 0.0; }; };
  if (xyz[0].type == Scalar::f32 && xyz[1].type == Scalar::f32 && xyz[2].type == Scalar::f32) {
    for (std::size_t i = 0; i < h.points; ++i) {
      sink.put(i, detail::load_raw<float>(xyz[0].start + i * xyz[0].stride),
               detail::load_raw<float>(xyz[1].start + i * xyz[1].stride),
               detail::load_raw<float>(xyz[2].start + i * xyz[2].stride), label_of(i));
    }
  } else {
    for (std::size_t i = 0; i < h.points; ++i) sink.put(i, xyz[0].at(i), xyz[1].at(i), xyz[2].at(i), label_of(i));
  }
  sink.finish();
}

void read_binary(std::string_view data, const std::string& name, const PcdHeader& h, CloudFile& out) {
  const std::size_t available = data.size() - h.data_offset;
  if (available < h.data_bytes) {
    throw ReadError(name, at_byte(data.size()),
                    "truncated binary data (expected " + std::to_string(h.data_bytes) +
                        " bytes of points, found " + std::to_string(available) + ")");
  }
  const auto* base = reinterpret_cast<const unsigned char*>(data.data()) + h.data_offset;
  const auto column = [&](std::size_t f) { return FieldColumn{base + h.fields[f].offset, h.point_size, h.fields[f].type}; };
  const FieldColumn xyz[3] = {column(h.xyz[0]), column(h.xyz[1]), column(h.xyz[2])};
  const FieldColumn label = h.label ? column(*h.label) : FieldColumn{};
  extract_points(xyz, h.label ? &label : nullptr, h, out);
}

void read_compressed(std::string_view data, const std::string& name, const PcdHeader& h, CloudFile& out) {
  const std::size_t available = data.size() - h.data_offset;
  if (available < 8) {
    throw ReadError(name, at_byte(data.size()),
                    "truncated binary_compressed data (missing the 8-byte size prefix)");
  }
  const auto* prefix = reinterpret_cast<const unsigned char*>(data.data()) + h.data_offset;
  const auto compressed = detail::load_raw<std::uint32_t>(prefix);
  const auto uncompressed = detail::load_raw<std::uint32_t>(prefix + 4);
  if (uncompressed != h.data_bytes) {
    throw ReadError(name, at_byte(h.data_offset + 4),
                    "compressed size mismatch: block holds " + std::to_string(uncompressed) +
                        " bytes, the header's " + std::to_string(h.points) + " points need " +
                        std::to_string(h.data_bytes));
  }
  if (compressed > available - 8) {
    throw ReadError(name, at_byte(data.size()),
                    "truncated compressed data (expected " + std::to_string(compressed) + " bytes, found " +
                        std::to_string(available - 8) + ")");
  }
  if (uncompressed == 0) return;
  if (uncompressed > kMaxLzfRatio * compressed) {
    throw ReadError(name, at_byte(h.data_offset + 8),
                    "corrupt LZF stream: " + std::to_string(compressed) + " bytes cannot expand to " +
                        std::to_string(uncompressed));
  }
  const std::unique_ptr<unsigned char[]> soa(new unsigned char[uncompressed]);
  const unsigned int produced = lzf_decompress(prefix + 8, compressed, soa.get(), uncompressed);
  if (produced != uncompressed) {
    throw ReadError(name, at_byte(h.data_offset + 8),
                    "corrupt LZF stream (decompressed " + std::to_string(produced) + " of " +
                        std::to_string(uncompressed) + " bytes)");
  }
  // Per-field layout: all values of the first field, then all of the second, ...;
  // a field's block therefore starts at points * (its offset in an interleaved record).
  const auto column = [&](std::size_t f) {
    return FieldColumn{soa.get() + h.points * h.fields[f].offset, detail::scalar_size(h.fields[f].type), h.fields[f].type};
  };
  const FieldColumn xyz[3] = {column(h.xyz[0]), column(h.xyz[1]), column(h.xyz[2])};
  const FieldColumn label = h.label ? column(*h.label) : FieldColumn{};
  extract_points(xyz, h.label ? &label : nullptr, h, out);
}

}  // namespace

CloudFile read_pcd_buffer(std::string_view data, const std::string& name, const ReadLimits& limits) {
  detail::check_buffer(data, name, limits);
  const PcdHeader header = detail::parse_pcd_header(data, name, limits);
  CloudFile out;
  switch (header.data) {
    case detail::PcdData::ascii:
      out.format = "pcd-ascii";
      read_ascii(data, name, header, out);
      break;
    case detail::PcdData::binary:
      out.format = "pcd-binary";
      read_binary(data, name, header, out);
      break;
    case detail::PcdData::binary_compressed:
      out.format = "pcd-binary_compressed";
      read_compressed(data, name, header, out);
      break;
  }
  return out;
}

}  // namespace cloudshape::io
