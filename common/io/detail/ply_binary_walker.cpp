// Walks binary_little_endian PLY records: bulk copies for fixed-size elements, one property at
// a time for elements with lists. Every read is bounds-checked against the buffer.
#include "io/detail/ply_binary_walker.hpp"

#include <algorithm>

#include "io/detail/binary_scalar.hpp"

namespace cloudshape::io::detail {
namespace {

bool fixed_size(const PlyElement& e, std::size_t& record_size) {
  record_size = 0;
  for (const auto& p : e.properties) {
    if (p.is_list) return false;
    record_size += scalar_size(p.type);
  }
  return true;
}

}  // namespace

PlyBinaryWalker::PlyBinaryWalker(std::string_view data, const PlyHeader& header, const std::string& name)
    : base_(reinterpret_cast<const unsigned char*>(data.data())),
      size_(data.size()),
      pos_(std::min(header.data_offset, data.size())),
      name_(name) {}

void PlyBinaryWalker::skip(const PlyElement& e) {
  if (std::size_t record_size = 0; fixed_size(e, record_size)) {
    bulk(e, record_size);
    return;
  }
  for (std::uint64_t r = 0; r < e.count; ++r) {
    for (const auto& p : e.properties) skip_property(p, e, r);
  }
}

void PlyBinaryWalker::vertices(const PlyElement& e, const AxisProperties& xyz, PointList& out) {
  if (std::size_t record_size = 0; fixed_size(e, record_size)) {
    std::array<std::size_t, 3> offsets{};
    std::array<Scalar, 3> types{};
    for (int a = 0; a < 3; ++a) {
      types[a] = e.properties[xyz[a]].type;
      for (std::size_t i = 0; i < xyz[a]; ++i) offsets[a] += scalar_size(e.properties[i].type);
    }
    const unsigned char* const start = bulk(e, record_size);
    out.reserve(static_cast<std::size_t>(e.count));
    for (std::size_t i = 0; i < e.count; ++i) {
      const unsigned char* record = start + i * record_size;
      out.emplace_back(load_scalar(record + offsets[0], types[0]), load_scalar(record + offsets[1], types[1]),
                       load_scalar(record + offsets[2], types[2]));
    }
    return;
  }
  // Every record holds at least one byte (a list length), which bounds the reservation.
  out.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(e.count, size_ - pos_)));
  for (std::uint64_t r = 0; r < e.count; ++r) {
    double values[3] = {0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
      const PlyProperty& p = e.properties[i];
      if (p.is_list) {
        skip_property(p, e, r);
        continue;
      }
      const unsigned char* value = take(scalar_size(p.type), e, r);
      for (int a = 0; a < 3; ++a) {
        if (xyz[a] == i) values[a] = load_scalar(value, p.type);
      }
    }
    out.emplace_back(values[0], values[1], values[2]);
  }
}

void PlyBinaryWalker::faces(const PlyElement& e, std::size_t indices, std::uint64_t vertex_count, Triangles& out) {
  // A face needs at least a one-byte length and one index byte per corner.
  out.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(e.count, (size_ - pos_) / 4)));
  for (std::uint64_t r = 0; r < e.count; ++r) {
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
      const PlyProperty& p = e.properties[i];
      if (i != indices) {
        skip_property(p, e, r);
        continue;
      }
      const std::uint64_t n = list_length(p, e, r);
      const std::size_t item = scalar_size(p.type);
      const std::size_t at = pos_;
      const unsigned char* items = take(list_bytes(n, item, e, r), e, r);
      TriangleFan fan;
      for (std::uint64_t k = 0; k < n; ++k) {
        std::uint64_t index = 0;
        if (!load_unsigned(items + k * item, p.type, index)) {
          throw ReadError(name_, at_byte(at + k * item), "face " + std::to_string(r) + ": negative vertex index");
        }
        if (index >= vertex_count) throw_index_out_of_range(name_, at_byte(at + k * item), r, index, vertex_count);
        fan.add(static_cast<std::uint32_t>(index), out);
      }
    }
  }
}

void PlyBinaryWalker::truncated(const PlyElement& e, std::uint64_t record) const {
  throw ReadError(name_, at_byte(size_),
                  "truncated binary data in " + element_name(e) + " (record " + std::to_string(record) + " of " +
                      std::to_string(e.count) + ")");
}

const unsigned char* PlyBinaryWalker::take(std::size_t n, const PlyElement& e, std::uint64_t record) {
  if (n > size_ - pos_) truncated(e, record);
  const unsigned char* p = base_ + pos_;
  pos_ += n;
  return p;
}

// All records of a fixed-size element at once; zero-sized records cost nothing however many.
const unsigned char* PlyBinaryWalker::bulk(const PlyElement& e, std::size_t record_size) {
  std::uint64_t total = 0;
  if (__builtin_mul_overflow(e.count, static_cast<std::uint64_t>(record_size), &total) || total > size_ - pos_) {
    throw ReadError(name_, at_byte(size_),
                    "truncated binary data in " + element_name(e) + " (expected " +
                        (total > 0 ? std::to_string(total) : std::string("more")) + " bytes, found " +
                        std::to_string(size_ - pos_) + ")");
  }
  return take(static_cast<std::size_t>(total), e, 0);
}

std::size_t PlyBinaryWalker::list_bytes(std::uint64_t n, std::size_t item, const PlyElement& e,
                                        std::uint64_t record) const {
  std::uint64_t bytes = 0;
  if (__builtin_mul_overflow(n, static_cast<std::uint64_t>(item), &bytes) || bytes > size_ - pos_) {
    truncated(e, record);
  }
  return static_cast<std::size_t>(bytes);
}

std::uint64_t PlyBinaryWalker::list_length(const PlyProperty& p, const PlyElement& e, std::uint64_t record) {
  const std::size_t at = pos_;
  std::uint64_t n = 0;
  if (!load_unsigned(take(scalar_size(p.count_type), e, record), p.count_type, n)) {
    throw ReadError(name_, at_byte(at),
                    "negative list length in " + element_name(e) + " (record " + std::to_string(record) + ")");
  }
  return n;
}

void PlyBinaryWalker::skip_property(const PlyProperty& p, const PlyElement& e, std::uint64_t record) {
  if (!p.is_list) {
    take(scalar_size(p.type), e, record);
    return;
  }
  const std::uint64_t n = list_length(p, e, record);
  take(list_bytes(n, scalar_size(p.type), e, record), e, record);
}

}  // namespace cloudshape::io::detail
