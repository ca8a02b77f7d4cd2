// Ground truth as JSON, written next to every synthetic cloud and read back by tests.
// Objects use the recognizer's output schema (INTERFACE.md) so results compare field by field.
#pragma once

#include "synth/ground_truth.hpp"

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace cloudshape::synth {

// How the cloud was made; recorded so a failing case can be regenerated and understood.
struct GenerationInfo {
  std::size_t points = 0;  // points actually written, outliers included
  std::uint64_t seed = 0;
  double noise_sigma = 0.0;       // absolute, in the cloud's unit
  double outlier_fraction = 0.0;  // relative to the clean cloud
  std::size_t outliers = 0;
  std::optional<Eigen::Vector3d> view;  // camera position when hidden points were removed
  std::optional<Eigen::Vector3d> density_falloff_from;  // see DensityVariation
  double patchiness = 0.0;
};

// {"shape", "dimensions": {name: value}, "pose": {"center": [x,y,z], "axes": [[...],[...],[...]]}}
nlohmann::json solid_to_json(const SolidSpec& spec);

// Inverse of solid_to_json. Throws std::invalid_argument naming the offending field.
SolidSpec solid_from_json(const nlohmann::json& object);

// {"source", "objects": [...], "points", "seed", "noise_sigma", "outlier_fraction", "outliers",
//  "view" (only with a view)}. With a view every object also carries "partial": true.
nlohmann::json ground_truth_json(const std::string& source, const std::vector<SolidSpec>& objects,
                                 const GenerationInfo& info);

// The "objects" array of a ground-truth (or recognizer) document as specs. Throws
// std::invalid_argument on a missing or malformed field or a shape it cannot model (e.g. unknown).
std::vector<SolidSpec> solids_from_ground_truth(const nlohmann::json& document);

}  // namespace cloudshape::synth
