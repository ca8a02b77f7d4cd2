// The one exception every cloud and mesh reader throws for bad input.
// Its message is a single line "<file>: <place>: <problem>" so a user can go straight to the fault.
#include "io/read_error.hpp"

#include <utility>

namespace cloudshape::io {
namespace {

// Parts may echo bytes from a hostile file; keeping what() on one printable line
// protects logs and terminals.
std::string one_line(std::string text) {
  for (char& c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) c = ' ';
  }
  return text;
}

}  // namespace

ReadError::ReadError(std::string file, std::string place, std::string problem)
    : std::runtime_error(one_line(file + ": " + place + ": " + problem)),
      file_(std::move(file)),
      place_(std::move(place)),
      problem_(std::move(problem)) {}

}  // namespace cloudshape::io
