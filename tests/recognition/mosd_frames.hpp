// The 45 real Kinect frames of shared/data/real/mosd_learn for the tests that read them: where they
// are (CI must have them; a checkout without shared/ skips), jittered copies, and shapes per
// object.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <string>

#include "geometry/point_cloud.hpp"
#include "geometry/voxel_grid.hpp"
#include "io/cloud_file.hpp"
#include "pipeline/result.hpp"
#include "synth/perturb.hpp"

namespace cloudshape::mosd {

inline const std::filesystem::path kDir =
    std::filesystem::path(CLOUDSHAPE_SHARED_DATA_DIR) / "real/mosd_learn";

inline bool data_missing() {
  if (std::filesystem::exists(kDir / "learn0.pcd")) return false;
  const char* ci = std::getenv("CI");
  if (ci && std::string(ci) == "true") ADD_FAILURE() << kDir << " missing on CI";
  return true;
}

inline std::string frame_path(int frame) {
  return (kDir / ("learn" + std::to_string(frame) + ".pcd")).string();
}

// Every coordinate moved by Gaussian noise of `share` of the points' spacing, as
// `cloudshape-bench --scenes --jitter` moves them (there seed 1000003 * scene + run).
inline PointList jittered(PointList points, double share, std::uint64_t seed) {
  const double sigma = share * geometry::mean_nearest_neighbour_distance(points);
  if (!(sigma > 0.0)) return points;
  std::mt19937_64 rng(seed);
  synth::add_gaussian_noise(points, sigma, rng);
  return points;
}

// Per labelled object of at least 50 points (SOURCES.md: label / 10, from 2 on), the shape of the
// report most of whose points are its; "" when none is.
inline std::map<std::uint32_t, std::string> shapes_of_objects(
    const io::CloudFile& file, const pipeline::RecognitionResult& result) {
  std::map<std::uint32_t, std::size_t> points_of;
  for (std::uint32_t label : file.labels)
    if (label >= 20) ++points_of[label / 10];
  std::map<std::uint32_t, std::string> shapes;
  for (const auto& [object, points] : points_of)
    if (points >= 50) shapes[object] = "";
  for (const auto& o : result.objects) {
    std::map<std::uint32_t, std::size_t> votes;
    for (std::uint32_t i : o.point_indices) ++votes[file.labels[i] / 10];
    for (const auto& [object, n] : votes)
      if (shapes.count(object) != 0 && 2 * n > o.point_indices.size()) shapes[object] = o.shape;
  }
  return shapes;
}

}  // namespace cloudshape::mosd
