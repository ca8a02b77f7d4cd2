// The one exception every cloud and mesh reader throws for bad input.
// Its message is a single line "<file>: <place>: <problem>" so a user can go straight to the fault.
#pragma once

#include <stdexcept>
#include <string>

namespace cloudshape::io {

class ReadError : public std::runtime_error {
public:
  // `place` is "line 12", "byte 4096", "header", ... ; the parts are kept so callers
  // (and tests) can inspect them without parsing what().
  ReadError(std::string file, std::string place, std::string problem);

  const std::string& file() const noexcept { return file_; }
  const std::string& place() const noexcept { return place_; }
  const std::string& problem() const noexcept { return problem_; }

private:
  std::string file_;
  std::string place_;
  std::string problem_;
};

}  // namespace cloudshape::io
