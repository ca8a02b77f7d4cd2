// Scalar types shared by the PCD and PLY binary layouts, and how to load one from raw bytes.
// Loads go through memcpy: file data has no alignment guarantee and the host is little-endian.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace cloudshape::io::detail {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "binary PCD/PLY loading assumes a little-endian host");

enum class Scalar : std::uint8_t { i8, u8, i16, u16, i32, u32, i64, u64, f32, f64 };

constexpr std::size_t scalar_size(Scalar s) {
  switch (s) {
    case Scalar::i8:
    case Scalar::u8: return 1;
    case Scalar::i16:
    case Scalar::u16: return 2;
    case Scalar::i32:
    case Scalar::u32:
    case Scalar::f32: return 4;
    case Scalar::i64:
    case Scalar::u64:
    case Scalar::f64: return 8;
  }
  return 0;
}

constexpr bool is_integer(Scalar s) { return s != Scalar::f32 && s != Scalar::f64; }

template <typename T>
inline T load_raw(const unsigned char* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return value;
}

// The caller guarantees scalar_size(s) readable bytes at p.
inline double load_scalar(const unsigned char* p, Scalar s) {
  switch (s) {
    case Scalar::i8: return load_raw<std::int8_t>(p);
    case Scalar::u8: return load_raw<std::uint8_t>(p);
    case Scalar::i16: return load_raw<std::int16_t>(p);
    case Scalar::u16: return load_raw<std::uint16_t>(p);
    case Scalar::i32: return load_raw<std::int32_t>(p);
    case Scalar::u32: return load_raw<std::uint32_t>(p);
    case Scalar::i64: return static_cast<double>(load_raw<std::int64_t>(p));
    case Scalar::u64: return static_cast<double>(load_raw<std::uint64_t>(p));
    case Scalar::f32: return load_raw<float>(p);
    case Scalar::f64: return load_raw<double>(p);
  }
  return 0.0;
}

// A value parsed from text, narrowed to the type the header declares for it, so an ascii
// file yields exactly the points its binary twin does (a "float" field holds a float).
inline double as_declared(double value, Scalar s) {
  return s == Scalar::f32 ? static_cast<double>(static_cast<float>(value)) : value;
}

// For list lengths and indices: exact for every integer type, and a negative value
// is reported instead of wrapping into a huge count.
inline bool load_unsigned(const unsigned char* p, Scalar s, std::uint64_t& value) {
  switch (s) {
    case Scalar::u8: value = load_raw<std::uint8_t>(p); return true;
    case Scalar::u16: value = load_raw<std::uint16_t>(p); return true;
    case Scalar::u32: value = load_raw<std::uint32_t>(p); return true;
    case Scalar::u64: value = load_raw<std::uint64_t>(p); return true;
    case Scalar::i8: {
      const auto v = load_raw<std::int8_t>(p);
      value = static_cast<std::uint64_t>(v);
      return v >= 0;
    }
    case Scalar::i16: {
      const auto v = load_raw<std::int16_t>(p);
      value = static_cast<std::uint64_t>(v);
      return v >= 0;
    }
    case Scalar::i32: {
      const auto v = load_raw<std::int32_t>(p);
      value = static_cast<std::uint64_t>(v);
      return v >= 0;
    }
    case Scalar::i64: {
      const auto v = load_raw<std::int64_t>(p);
      value = static_cast<std::uint64_t>(v);
      return v >= 0;
    }
    case Scalar::f32:
    case Scalar::f64: return false;
  }
  return false;
}

}  // namespace cloudshape::io::detail
