// Whether two poses' axes agree as far as INTERFACE.md pins them down: each axis up to its sign
// (not the cone's or frustum's axis 0), none for a sphere, a plane instead of a pair for equal box edges.
#pragma once

#include <string>

#include "pipeline/result.hpp"

namespace cloudshape::testing {

// Empty when `actual`'s axes are `expected`'s up to the freedom the contract leaves for
// `expected`'s shape and dimensions, within `tolerance` per component; else why not.
// Two dimensions count as equal when they agree within `tolerance` relative.
std::string axes_difference(const pipeline::ObjectResult& actual, const pipeline::ObjectResult& expected,
                            double tolerance);

}  // namespace cloudshape::testing
