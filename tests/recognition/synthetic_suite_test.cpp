// Acceptance on noise-free synthetic clouds: all six solids in random poses, three
// scales (any unit works) and two densities: >= 98% right shape, every dimension within 1%.
#include <gtest/gtest.h>

#include <random>

#include "config/pipeline_config.hpp"
#include "pipeline/recognize.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

namespace cloudshape {
namespace {

constexpr double kPi = 3.14159265358979323846;

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b, bool sign_matters) {
  double c = a.normalized().dot(b.normalized());
  if (!sign_matters) c = std::abs(c);
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / kPi;
}

struct Tally {
  int clouds = 0, right_shape = 0, dims_within_1pct = 0, pose_ok = 0;
};

// Axes whose dimension ties another (a near-cube) are not identifiable, so only the
// distinct ones are compared; the sign is free except for the cone's axis.
bool pose_matches(const pipeline::ObjectResult& got, const synth::SolidSpec& truth, double size) {
  if ((got.center - truth.pose.center).norm() > 0.01 * size) return false;
  switch (truth.kind) {
    case synth::ShapeKind::sphere:
    case synth::ShapeKind::tetrahedron:
      return true;
    case synth::ShapeKind::cone:
      return angle_deg(got.axes.row(0), truth.pose.axes.row(0), true) < 1.0;
    case synth::ShapeKind::cylinder:
    case synth::ShapeKind::pentagonal_prism:
      return angle_deg(got.axes.row(0), truth.pose.axes.row(0), false) < 1.0;
    case synth::ShapeKind::box:
      for (int k = 0; k < 3; ++k) {
        bool distinct = true;
        for (int j = 0; j < 3; ++j)
          if (j != k && std::abs(truth.dimensions[j].second / truth.dimensions[k].second - 1) < 0.03)
            distinct = false;
        if (distinct && angle_deg(got.axes.row(k), truth.pose.axes.row(k), false) > 1.0) return false;
      }
      return true;
  }
  return false;
}

TEST(SyntheticSuite, SixShapesRandomPosesThreeScalesTwoDensities) {
  const config::PipelineConfig cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  Tally all;
  std::map<std::string, Tally> per_shape;
  std::uint64_t seed = 20261123;
  for (auto kind : synth::all_shape_kinds()) {
    for (double scale : {1.0, 30.0, 800.0}) {
      for (std::size_t points : {5000u, 100000u}) {
        for (int pose = 0; pose < 3; ++pose) {
          std::mt19937_64 rng(seed++);
          const synth::SolidSpec truth = synth::random_solid(kind, rng, scale);
          const PointList cloud = synth::sample_solid_surface(truth, points, rng);
          const auto result = pipeline::recognize_cloud(cloud, cfg, "suite");
          ASSERT_EQ(result.objects.size(), 1u);
          const auto& got = result.objects.front();
          Tally& t = per_shape[synth::to_string(kind)];
          ++t.clouds;
          ++all.clouds;
          if (got.shape != synth::to_string(kind)) {
            ADD_FAILURE() << synth::to_string(kind) << " scale " << scale << " points " << points
                          << " seed " << seed - 1 << " recognised as " << got.shape << " "
                          << got.reason;
            continue;
          }
          ++t.right_shape;
          ++all.right_shape;
          EXPECT_FALSE(got.partial) << synth::to_string(kind) << " seen whole, seed " << seed - 1;
          bool within = got.dimensions.size() == truth.dimensions.size();
          for (std::size_t d = 0; within && d < truth.dimensions.size(); ++d) {
            const double rel = std::abs(got.dimensions[d].second / truth.dimensions[d].second - 1.0);
            EXPECT_LT(rel, 0.01) << synth::to_string(kind) << " " << truth.dimensions[d].first
                                 << " seed " << seed - 1;
            within = within && rel < 0.01;
          }
          all.dims_within_1pct += within;
          const bool pose_ok = pose_matches(got, truth, synth::characteristic_size(truth));
          EXPECT_TRUE(pose_ok) << synth::to_string(kind) << " pose, seed " << seed - 1;
          all.pose_ok += pose_ok;
        }
      }
    }
  }
  for (const auto& [shape, t] : per_shape)
    std::printf("%-17s %d/%d right shape\n", shape.c_str(), t.right_shape, t.clouds);
  std::printf("all: %d/%d right shape, %d with every dimension within 1%%, %d poses within 1%%/1deg\n",
              all.right_shape, all.clouds, all.dims_within_1pct, all.pose_ok);
  EXPECT_GE(all.right_shape, static_cast<int>(std::ceil(0.98 * all.clouds)));
}

}  // namespace
}  // namespace cloudshape
