#include "geometry/circle.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {

std::optional<FittedSolid> fit_sphere_solid(const SolveInput& in) {
  const auto fit = geometry::fit_sphere(in.cloud);
  if (!fit) return std::nullopt;
  FittedSolid out;
  out.shape = Shape::sphere;
  out.dimensions = {{"radius", fit->radius}};
  out.center = fit->center;
  const Point c = fit->center;
  const double r = fit->radius;
  out.signed_distance = [c, r](const Point& p) { return (p - c).norm() - r; };
  return out;
}

}  // namespace cloudshape::pipeline
