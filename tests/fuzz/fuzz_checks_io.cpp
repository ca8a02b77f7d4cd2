// The reader fuzz checks: every point a reader returns is finite and within the limits, every
// mesh index points at a vertex; refusing the input with a ReadError is always allowed.
#include <cstdint>
#include <string>

#include "fuzz_checks.hpp"
#include "io/mesh_reader.hpp"
#include "io/pcd_reader.hpp"
#include "io/ply_reader.hpp"
#include "io/read_error.hpp"
#include "io/xyz_reader.hpp"

namespace cloudshape::fuzz {
namespace {

std::string cloud_problems(const io::CloudFile& cloud, const io::ReadLimits& limits) {
  if (cloud.points.size() + cloud.non_finite_dropped > limits.max_points) {
    return std::to_string(cloud.points.size() + cloud.non_finite_dropped) + " points read, over the limit";
  }
  for (const Point& p : cloud.points) {
    if (!p.allFinite()) return "a non-finite point was returned";
  }
  if (cloud.format.empty()) return "no format reported";
  return {};
}

template <class Read>
std::string read_cloud_checked(Read read, std::string_view bytes, const char* name) {
  const io::ReadLimits limits = fuzz_limits();
  try {
    return cloud_problems(read(bytes, name, limits), limits);
  } catch (const io::ReadError& e) {
    if (std::string(e.what()).find('\n') != std::string::npos) return "a ReadError message spans lines";
    return {};
  }
}

std::string mesh_problems(std::string_view bytes) {
  try {
    const io::Mesh mesh = io::read_ply_mesh_buffer(bytes, "fuzz.ply", fuzz_limits());
    if (mesh.triangles.empty()) return "a mesh without triangles was returned";
    for (const auto& t : mesh.triangles) {
      for (std::uint32_t i : t) {
        if (i >= mesh.vertices.size()) return "a triangle index beyond the vertices";
      }
    }
    for (const Point& p : mesh.vertices) {
      if (!p.allFinite()) return "a non-finite mesh vertex was returned";
    }
  } catch (const io::ReadError&) {
  }
  return {};
}

}  // namespace

std::string check_pcd_input(std::string_view bytes) {
  return read_cloud_checked(io::read_pcd_buffer, bytes, "fuzz.pcd");
}

std::string check_ply_input(std::string_view bytes) {
  std::string problem = read_cloud_checked(io::read_ply_buffer, bytes, "fuzz.ply");
  return problem.empty() ? mesh_problems(bytes) : problem;
}

std::string check_xyz_input(std::string_view bytes) {
  return read_cloud_checked(io::read_xyz_buffer, bytes, "fuzz.xyz");
}

}  // namespace cloudshape::fuzz
