#include "speed_shapes.hpp"

#include <memory>

#include "synth/ground_truth.hpp"
#include "synth/mesh_sampling.hpp"
#include "synth/mesh_solids.hpp"
#include "synth/pose.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

namespace cloudshape::bench {

std::optional<SpeedShape> speed_shape(const std::string& name, double size, std::uint64_t seed) {
  if (const auto kind = synth::shape_kind_from_string(name)) {
    std::mt19937_64 solid_rng(seed * 1000003u + static_cast<std::uint64_t>(*kind));
    const synth::SolidSpec spec = synth::random_solid(*kind, solid_rng, size);
    return SpeedShape{name, [spec](std::size_t n, std::mt19937_64& rng) { return synth::sample_solid_surface(spec, n, rng); }};
  }
  // The shapes beyond the six as meshes: an L-profile (non-convex, six sides) and a frustum whose
  // top is half its base, both size across and size long, posed at random.
  // A fixed constant per name (std::hash differs between standard libraries).
  std::mt19937_64 pose_rng(seed * 1000003u + (name == "prism" ? 101u : 102u));
  const synth::Pose pose = synth::random_pose(pose_rng, size);
  std::shared_ptr<const synth::SolidMesh> mesh;
  if (name == "prism") {
    const double a = 0.5 * size, b = 0.1 * size;
    const geometry::Polygon2 l_profile = {{-a, -a}, {a, -a}, {a, -b}, {-b, -b}, {-b, a}, {-a, a}};
    mesh = std::make_shared<synth::SolidMesh>(synth::prism_mesh(l_profile, size, pose));
  } else if (name == "frustum") {
    mesh = std::make_shared<synth::SolidMesh>(synth::frustum_mesh(0.5 * size, 0.25 * size, size, pose));
  } else {
    return std::nullopt;
  }
  return SpeedShape{name, [mesh](std::size_t n, std::mt19937_64& rng) {
                      return synth::sample_mesh_surface(mesh->vertices, mesh->triangles, n, rng);
                    }};
}

}  // namespace cloudshape::bench
