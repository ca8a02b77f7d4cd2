// Shared by the per-shape positive tests: a cloud of one solid under a condition (noise,
// outliers, one camera), recognition, and the errors of the result against the ground truth.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "pipeline/result.hpp"
#include "synth/ground_truth.hpp"

namespace cloudshape::positive {

// Noise is a share of the solid's characteristic size; outliers a share of the surface points,
// uniform in the cloud's bounding box (synth::add_outliers). With a view direction, a camera
// 3 sizes from the centre along it keeps only what it sees.
struct Condition {
  std::string name;
  std::size_t points = 10000;
  double noise = 0.0;
  double outliers = 0.0;
  std::optional<Eigen::Vector3d> view_direction;
};

Condition noisy();                // sigma 0.5% of size
Condition noisy_with_outliers();  // sigma 0.5% of size and 3% outliers
Condition seen_from(const Eigen::Vector3d& direction, double noise = 0.0);

PointList make_cloud(const synth::SolidSpec& truth, const Condition& condition, std::uint64_t seed);

// What a result gets wrong. Dimensions relative to the true value, the centre relative to the
// solid's characteristic size, axes as the largest angle over what the shape defines: every
// box axis (sign free), a cylinder's or prism's axis (sign free) and the prism's turn about it
// (its side normals), the cone's signed axis, the tetrahedron's four vertex directions.
struct Errors {
  std::vector<double> dimensions;
  double center = 0.0;
  double axes_deg = 0.0;
};

Errors errors_of(const pipeline::ObjectResult& got, const synth::SolidSpec& truth);

struct Tolerance {
  double dimension;  // relative
  double center;     // share of the characteristic size
  double axes_deg;
};

// Largest errors over a set of runs, printed once per condition so the tolerances can be
// re-measured from the test log.
struct Worst {
  std::vector<double> dimensions;
  double center = 0.0;
  double axes_deg = 0.0;
  int runs = 0;
  void add(const Errors& e);
  void print(const std::string& shape, const std::string& condition) const;
};

// Recognises the cloud and expects one object of the truth's shape, its partial flag as
// given, and every error within the tolerance. Returns the errors (empty dimensions when the
// shape was wrong).
Errors expect_recognised(const PointList& cloud, const synth::SolidSpec& truth, bool partial,
                         const Tolerance& tolerance, const std::string& trace);

// One solid per seed (drawn from the seed's generator) under the condition made for it; each
// recognised within the tolerance. Prints the worst errors as "[measured] shape condition ...".
using SolidMaker = std::function<synth::SolidSpec(std::mt19937_64&)>;
using ConditionMaker = std::function<Condition(const synth::SolidSpec&, std::mt19937_64&)>;
void check_seeds(const std::vector<std::uint64_t>& seeds, const SolidMaker& solid,
                 const ConditionMaker& condition, bool partial, const Tolerance& tolerance);

// A direction at `degrees` from the solid's axes[0], at a random turn about it.
Eigen::Vector3d from_axis(const synth::SolidSpec& truth, double degrees, std::mt19937_64& rng);

// A random rigid pose around the origin and a size spread over three decades, so no test
// depends on the unit.
synth::Pose random_pose(std::mt19937_64& rng, double size);
double random_size(std::mt19937_64& rng);

}  // namespace cloudshape::positive
