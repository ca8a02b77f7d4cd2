// The solids the speed table times, by name: the six (synth::ShapeKind, random proportions) and
// the shapes beyond them (`prism`: an L-profile, `frustum`), each sampled on its whole surface.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <string>

#include "geometry/point_cloud.hpp"

namespace cloudshape::bench {

struct SpeedShape {
  std::string name;
  // `points` surface points of the one solid of this shape (the same solid at every size).
  std::function<PointList(std::size_t points, std::mt19937_64& rng)> sample;
};

// Nothing for an unknown name. `size`: the solid's largest extent; `seed` draws its proportions.
std::optional<SpeedShape> speed_shape(const std::string& name, double size, std::uint64_t seed);

}  // namespace cloudshape::bench
