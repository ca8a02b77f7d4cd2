// A read-only memory map of a whole file, so large recordings are read without a copy.
// Opening problems are ReadErrors in the readers' "<file>: <place>: <problem>" form.
#include "io/detail/mapped_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/detail/input.hpp"
#include "io/read_error.hpp"

namespace cloudshape::io::detail {
namespace {

struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

MappedFile::MappedFile(const std::string& path, const ReadLimits& limits) {
  const Fd file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) throw ReadError(path, "open", std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(file.fd, &st) != 0) throw ReadError(path, "open", std::string("cannot stat: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw ReadError(path, "open", "cannot open: is a directory");
  if (!S_ISREG(st.st_mode)) {
    throw ReadError(path, "open", "not a regular file (a recording is read by seeking in it)");
  }
  if (st.st_size == 0) throw ReadError(path, at_byte(0), "empty file");
  size_ = static_cast<std::size_t>(st.st_size);
  if (size_ > limits.max_bytes) {
    throw ReadError(path, at_byte(limits.max_bytes),
                    "input is " + std::to_string(size_) + " bytes, more than the limit of " +
                        std::to_string(limits.max_bytes) + " bytes");
  }
  data_ = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, file.fd, 0);
  if (data_ == MAP_FAILED) {
    data_ = nullptr;
    throw ReadError(path, "open", std::string("cannot map: ") + std::strerror(errno));
  }
  // Read front to back: let the kernel read ahead.
  ::madvise(data_, size_, MADV_SEQUENTIAL);
}

MappedFile::~MappedFile() {
  if (data_ != nullptr) ::munmap(data_, size_);
}

}  // namespace cloudshape::io::detail
