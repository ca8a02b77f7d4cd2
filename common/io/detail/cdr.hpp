// Plain CDR (XCDR1, as ROS 2 puts on the wire and in recordings): bounded reads and aligned writes.
// Alignment counts from after the 4-byte encapsulation header; either byte order is read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "io/read_error.hpp"

namespace cloudshape::io::detail::cdr {

class Reader {
public:
  // ReadError(file, place, ...) for a missing or unknown encapsulation header.
  Reader(std::string_view bytes, const std::string& file, std::string place)
      : data_(bytes), file_(file), place_(std::move(place)) {
    if (data_.size() < 4) fail("CDR: " + std::to_string(data_.size()) + " bytes, shorter than the encapsulation header");
    const auto kind = static_cast<std::uint8_t>(data_[1]);
    if (data_[0] != 0 || kind > 1) {
      fail("CDR: encapsulation kind " + std::to_string(static_cast<std::uint8_t>(data_[0])) + "," +
           std::to_string(kind) + " is not plain CDR (0,0 big-endian or 0,1 little-endian)");
    }
    swap_ = kind == 0;
    pos_ = 4;
  }

  std::uint8_t u8(const char* field) { return static_cast<std::uint8_t>(take(1, 1, field)[0]); }
  bool boolean(const char* field) { return u8(field) != 0; }
  std::uint32_t u32(const char* field) {
    std::uint32_t value;
    std::memcpy(&value, take(4, 4, field).data(), 4);
    return swap_ ? __builtin_bswap32(value) : value;
  }
  std::int32_t i32(const char* field) { return static_cast<std::int32_t>(u32(field)); }

  // A length counting the terminating NUL, then the characters and the NUL.
  std::string string(const char* field) {
    const std::uint32_t n = u32(field);
    if (n == 0) return {};  // some writers send an empty string as length 0
    const std::string_view s = take(n, 1, field);
    if (s.back() != '\0') fail("CDR: string '" + std::string(field) + "' is not NUL-terminated");
    return std::string(s.substr(0, s.size() - 1));
  }

  // A sequence length, checked against what is left so a lying count allocates nothing.
  std::uint32_t count(const char* field, std::size_t min_element_size) {
    const std::uint32_t n = u32(field);
    if (min_element_size > 0 && n > remaining() / min_element_size) {
      fail("CDR: sequence '" + std::string(field) + "' claims " + std::to_string(n) + " elements, only " +
           std::to_string(remaining()) + " bytes remain");
    }
    return n;
  }

  std::string_view take(std::size_t n, std::size_t align, const char* field) {
    const std::size_t padding = (align - (pos_ - 4) % align) % align;
    if (padding > data_.size() - pos_ || n > data_.size() - pos_ - padding) {
      fail("CDR: field '" + std::string(field) + "' runs past the end of the " + std::to_string(data_.size()) +
           "-byte message");
    }
    pos_ += padding;
    const std::string_view out = data_.substr(pos_, n);
    pos_ += n;
    return out;
  }

  std::size_t remaining() const { return data_.size() - pos_; }
  [[noreturn]] void fail(const std::string& problem) const { throw ReadError(file_, place_, problem); }

private:
  std::string_view data_;
  const std::string& file_;
  std::string place_;
  std::size_t pos_ = 0;
  bool swap_ = false;
};

// Little-endian CDR, the encapsulation header included.
class Writer {
public:
  Writer() { out_.assign("\x00\x01\x00\x00", 4); }

  void u8(std::uint8_t v) { out_.push_back(static_cast<char>(v)); }
  void u32(std::uint32_t v) {
    align(4);
    out_.append(reinterpret_cast<const char*>(&v), 4);
  }
  void string(std::string_view s) {
    u32(static_cast<std::uint32_t>(s.size() + 1));
    out_.append(s);
    out_.push_back('\0');
  }
  void bytes(const void* data, std::size_t n) { out_.append(static_cast<const char*>(data), n); }
  const std::string& str() const { return out_; }
  std::string take() { return std::move(out_); }

private:
  void align(std::size_t a) { out_.append((a - (out_.size() - 4) % a) % a, '\0'); }
  std::string out_;
};

}  // namespace cloudshape::io::detail::cdr
