// Getting a file's bytes into memory under the ReadLimits, plus the small wording helpers
// that keep every reader's error messages in the same "<file>: <place>: <problem>" shape.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "io/cloud_file.hpp"

namespace cloudshape::io::detail {

// ReadError when the file cannot be opened, is empty, or is larger than limits.max_bytes
// (checked before the contents are read).
std::string read_file_bytes(const std::string& path, const ReadLimits& limits);

// ReadError when a caller-supplied buffer is empty or larger than limits.max_bytes.
void check_buffer(std::string_view data, const std::string& name, const ReadLimits& limits);

// A token from the file, shortened and made printable, in single quotes.
std::string quoted(std::string_view token);

std::string at_line(std::size_t line);
std::string at_byte(std::size_t byte);

// The place used for problems with the header as a whole (a missing field, ...).
inline constexpr const char* kHeader = "header";

}  // namespace cloudshape::io::detail
