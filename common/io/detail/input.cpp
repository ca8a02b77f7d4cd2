// Getting a file's bytes into memory under the ReadLimits, plus the small wording helpers
// that keep every reader's error messages in the same "<file>: <place>: <problem>" shape.
#include "io/detail/input.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <system_error>

#include "io/read_error.hpp"

namespace cloudshape::io::detail {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

ReadError too_big(const std::string& name, std::size_t size, const ReadLimits& limits) {
  return ReadError(name, at_byte(limits.max_bytes),
                   "input is " + std::to_string(size) + " bytes, more than the limit of " +
                       std::to_string(limits.max_bytes) + " bytes");
}

}  // namespace

std::string read_file_bytes(const std::string& path, const ReadLimits& limits) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw ReadError(path, "open", "cannot open: is a directory");
  }
  const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) {
    throw ReadError(path, "open", std::string("cannot open: ") + std::strerror(errno));
  }
  // A regular file's size is known up front, so the limit is enforced before any
  // allocation; pipes and devices are read in chunks and stopped at the limit.
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > limits.max_bytes) throw too_big(path, size, limits);

  std::string bytes;
  if (!ec) bytes.reserve(static_cast<std::size_t>(size));
  char chunk[1 << 16];
  for (;;) {
    const std::size_t got = std::fread(chunk, 1, sizeof chunk, file.get());
    if (got > 0) {
      if (bytes.size() + got > limits.max_bytes) throw too_big(path, bytes.size() + got, limits);
      bytes.append(chunk, got);
    }
    if (got < sizeof chunk) break;
  }
  if (std::ferror(file.get())) {
    throw ReadError(path, at_byte(bytes.size()), std::string("read failed: ") + std::strerror(errno));
  }
  if (bytes.empty()) throw ReadError(path, at_byte(0), "empty file");
  return bytes;
}

void check_buffer(std::string_view data, const std::string& name, const ReadLimits& limits) {
  if (data.empty()) throw ReadError(name, at_byte(0), "empty file");
  if (data.size() > limits.max_bytes) throw too_big(name, data.size(), limits);
}

std::string quoted(std::string_view token) {
  constexpr std::size_t kMaxShown = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    out += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
  }
  if (token.size() > kMaxShown) out += "...";
  out += "'";
  return out;
}

std::string at_line(std::size_t line) { return "line " + std::to_string(line); }

std::string at_byte(std::size_t byte) { return "byte " + std::to_string(byte); }

}  // namespace cloudshape::io::detail
