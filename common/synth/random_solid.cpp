#include "synth/random_solid.hpp"
#include "synth/pose.hpp"
#include "synth/solid_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cloudshape::synth {

namespace {

// Log-uniform, so a ratio and its inverse are equally likely.
double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

}  // namespace

SolidSpec random_solid(ShapeKind kind, std::mt19937_64& rng, double size) {
  if (!(size > 0.0)) throw std::invalid_argument("random_solid: size must be positive");
  std::vector<double> values;
  switch (kind) {
    case ShapeKind::box: {
      std::uniform_real_distribution<double> fraction(1.0 / 3.0, 1.0);
      values = {size, size * fraction(rng), size * fraction(rng)};
      break;
    }
    case ShapeKind::tetrahedron:
      values = {size};
      break;
    case ShapeKind::pentagonal_prism: {
      const double height_over_width = log_uniform(rng, 1.0 / 3.0, 3.0);
      const double width_per_side = 2.0 * pentagon_circumradius(1.0);
      const double width = size / std::max(1.0, height_over_width);
      values = {width / width_per_side, width * height_over_width};
      break;
    }
    case ShapeKind::cone:
    case ShapeKind::cylinder: {
      const double height_over_radius = log_uniform(rng, 0.5, 4.0);
      const double radius = size / std::max(2.0, height_over_radius);
      values = {radius, radius * height_over_radius};
      break;
    }
    case ShapeKind::sphere:
      values = {size / 2.0};
      break;
  }
  return make_solid(kind, values, random_pose(rng, size));
}

}  // namespace cloudshape::synth
