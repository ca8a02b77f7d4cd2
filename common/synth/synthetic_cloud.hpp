// One call from ground-truth solids to a finished test cloud: sample, view, noise, outliers.
// Shared by the cloudshape-synth tool and by tests that need a cloud without files.
#pragma once

#include "geometry/point_cloud.hpp"
#include "synth/density.hpp"
#include "synth/ground_truth.hpp"
#include "synth/ground_truth_json.hpp"

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace cloudshape::synth {

struct CloudOptions {
  std::size_t points = 20000;  // surface points, before outliers are added
  double noise_sigma = 0.0;    // absolute, per coordinate
  double outlier_fraction = 0.0;
  std::optional<Eigen::Vector3d> view;  // camera position; hidden points removed when set
  DensityVariation density;             // uneven sampling; the count is still `points`
};

struct SyntheticCloud {
  PointList points;
  std::vector<SolidSpec> objects;
  GenerationInfo info;
};

// Splits options.points among the objects by surface area, samples them, keeps what the camera
// sees (exactly: solid_visibility.hpp; the count is kept at options.points via sample_visible),
// then adds noise and outliers, in that order. All randomness comes from `seed`, so the same
// arguments give the same cloud. Throws std::invalid_argument for an empty object list or bad
// options.
SyntheticCloud make_synthetic_cloud(const std::vector<SolidSpec>& objects,
                                    const CloudOptions& options, std::uint64_t seed);

// Rebuilds the exact cloud a ground-truth document (ground_truth_json of a make_synthetic_cloud
// result, as the tool writes) describes, bit for bit on the same platform. Throws
// std::invalid_argument if a field is missing or malformed.
SyntheticCloud regenerate_from_ground_truth(const nlohmann::json& document);

}  // namespace cloudshape::synth
