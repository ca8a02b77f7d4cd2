#include "render/wireframe.hpp"

#include <string_view>
#include <utility>

#include "render/wireframe_shapes.hpp"

namespace cloudshape::render {
namespace {

using WireframeFn = Wireframe (*)(const pipeline::ObjectResult&, const Eigen::Vector3d&);

constexpr std::pair<std::string_view, WireframeFn> kShapes[] = {
    {"box", box_wireframe},
    {"pentagonal_prism", pentagonal_prism_wireframe},
    {"tetrahedron", tetrahedron_wireframe},
    {"cylinder", cylinder_wireframe},
    {"cone", cone_wireframe},
    {"sphere", sphere_wireframe},
};

}  // namespace

Wireframe solid_wireframe(const pipeline::ObjectResult& object, const Eigen::Vector3d& toward_viewer) {
  for (const auto& [name, make] : kShapes)
    if (object.shape == name) return make(object, toward_viewer);
  return {};
}

}  // namespace cloudshape::render
