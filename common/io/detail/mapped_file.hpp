// A read-only memory map of a whole file, so large recordings are read without a copy.
// Opening problems are ReadErrors in the readers' "<file>: <place>: <problem>" form.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "io/cloud_file.hpp"

namespace cloudshape::io::detail {

class MappedFile {
public:
  // ReadError when the file cannot be opened or mapped, is empty, or exceeds limits.max_bytes.
  MappedFile(const std::string& path, const ReadLimits& limits);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view bytes() const { return {static_cast<const char*>(data_), size_}; }

private:
  void* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace cloudshape::io::detail
