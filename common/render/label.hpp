// The text drawn beside a recognised solid: its number, shape and dimensions (three
// significant digits, in the cloud's unit), how sure the recogniser is and whether it saw all.
#pragma once

#include <cstddef>
#include <string>

#include "pipeline/result.hpp"

namespace cloudshape::render {

// E.g. "1 box  l 0.301  w 0.201  h 0.1  97%" or "2 cylinder  r 0.0335  h 0.102  partial 80%".
std::string object_label(const pipeline::ObjectResult& object, std::size_t number);

// The short form for a second view: number and shape only, e.g. "1 box".
std::string object_tag(const pipeline::ObjectResult& object, std::size_t number);

}  // namespace cloudshape::render
