// Convex versus concave junctions: one solid's faces stay together, solids that touch or are
// stacked come apart where their surfaces meet in a valley.
#include <gtest/gtest.h>

#include "config/pipeline_config.hpp"
#include "segment/segment_scene.hpp"
#include "synth/ground_truth.hpp"
#include "synth/synthetic_cloud.hpp"

namespace cloudshape::segment {
namespace {

synth::Pose at(double x, double y, double z) {
  synth::Pose p;
  p.center = Eigen::Vector3d(x, y, z);
  return p;
}

// Segments of a cloud of the solids, each matched to the solid that holds most of its points.
struct Split {
  std::size_t segments = 0;
  std::vector<double> purity;  // per segment: share of its points from one solid
  std::vector<std::size_t> owner;
};

Split split(const std::vector<synth::SolidSpec>& solids, std::size_t points, std::uint64_t seed,
            std::optional<Eigen::Vector3d> view = std::nullopt) {
  synth::CloudOptions opts;
  opts.points = points;
  opts.view = view;
  // Each solid sampled alone so that every point's solid is known.
  PointList cloud;
  std::vector<std::size_t> solid_of;
  for (std::size_t k = 0; k < solids.size(); ++k) {
    const PointList part = synth::make_synthetic_cloud({solids[k]}, opts, seed + k).points;
    cloud.insert(cloud.end(), part.begin(), part.end());
    solid_of.insert(solid_of.end(), part.size(), k);
  }
  const SceneSegmentation s = segment_scene(cloud, GridLayout{}, config::PipelineConfig{}.segment);
  Split out;
  out.segments = s.objects.size();
  for (const auto& object : s.objects) {
    std::vector<std::size_t> votes(solids.size(), 0);
    for (std::uint32_t i : object) ++votes[solid_of[i]];
    const auto best = std::max_element(votes.begin(), votes.end());
    out.owner.push_back(static_cast<std::size_t>(best - votes.begin()));
    out.purity.push_back(static_cast<double>(*best) / static_cast<double>(object.size()));
  }
  return out;
}

TEST(SegmentConvexity, OneSolidsFacesStayTogether) {
  for (synth::ShapeKind kind : {synth::ShapeKind::box, synth::ShapeKind::tetrahedron, synth::ShapeKind::cone,
                                synth::ShapeKind::pentagonal_prism, synth::ShapeKind::cylinder}) {
    const std::vector<double> dims = kind == synth::ShapeKind::box ? std::vector<double>{3, 2, 1}
                                     : kind == synth::ShapeKind::tetrahedron ? std::vector<double>{2}
                                                                              : std::vector<double>{1, 2};
    const auto solid = synth::make_solid(kind, dims, at(0, 0, 0));
    EXPECT_EQ(split({solid}, 10000, 3).segments, 1u) << synth::to_string(kind);
    EXPECT_EQ(split({solid}, 10000, 3, Eigen::Vector3d(5, 6, 4)).segments, 1u) << synth::to_string(kind) << " view";
  }
}

// DISABLED (issue 10, left): unorganized clouds have no viewpoint, and normals oriented away from
// a component's centroid point the wrong way near where two solids meet, so the valley between
// them reads as convex; the solids stay one segment. Organized clouds orient towards the sensor.
// A box on a box: the lower box's top meets the upper box's sides in a concave valley.
TEST(SegmentConvexity, DISABLED_ABoxOnABoxComesApart) {
  const Split s = split({synth::make_solid(synth::ShapeKind::box, {4, 3, 1}, at(0, 0, 0.5)),
                         synth::make_solid(synth::ShapeKind::box, {2, 1.5, 1}, at(0.3, 0.2, 1.5))},
                        20000, 5, Eigen::Vector3d(3, -6, 7));
  ASSERT_EQ(s.segments, 2u);
  EXPECT_NE(s.owner[0], s.owner[1]);
  for (double p : s.purity) EXPECT_GT(p, 0.95);
}

// Two boxes of different heights side by side, touching: the taller one's side rises from the
// lower one's top in a valley.
TEST(SegmentConvexity, DISABLED_TwoTouchingBoxesComeApart) {
  const Split s = split({synth::make_solid(synth::ShapeKind::box, {2, 2, 1}, at(0, 0, 0.5)),
                         synth::make_solid(synth::ShapeKind::box, {2, 2, 2}, at(2, 0, 1))},
                        20000, 7, Eigen::Vector3d(1, -7, 6));
  ASSERT_EQ(s.segments, 2u);
  EXPECT_NE(s.owner[0], s.owner[1]);
  for (double p : s.purity) EXPECT_GT(p, 0.95);
}

// Two spheres that touch: their surfaces meet at a point in a valley all round.
TEST(SegmentConvexity, DISABLED_TwoTouchingSpheresComeApart) {
  const Split s = split({synth::make_solid(synth::ShapeKind::sphere, {1.0}, at(0, 0, 0)),
                         synth::make_solid(synth::ShapeKind::sphere, {1.0}, at(2, 0, 0))},
                        20000, 9);
  ASSERT_EQ(s.segments, 2u);
  EXPECT_NE(s.owner[0], s.owner[1]);
  for (double p : s.purity) EXPECT_GT(p, 0.95);
}

}  // namespace
}  // namespace cloudshape::segment
