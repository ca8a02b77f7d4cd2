// Convex versus concave junctions: one solid's faces stay together, solids that touch or are
// stacked come apart where their surfaces meet in a valley.
#include <gtest/gtest.h>

#include "config/pipeline_config.hpp"
#include "segment/segment_scene.hpp"
#include "synth/ground_truth.hpp"
#include "synth/solid_visibility.hpp"
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
  // Each solid sampled alone so that every point's solid is known; in a view, what the other
  // solids hide (a face where two touch, a top under what stands on it) is then removed, as a
  // camera would not see it.
  PointList cloud;
  std::vector<std::size_t> solid_of;
  for (std::size_t k = 0; k < solids.size(); ++k) {
    PointList part = synth::make_synthetic_cloud({solids[k]}, opts, seed + k).points;
    if (view) part = synth::visible_on_solids(part, solids, *view);
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

// A box on a box: the lower box's top meets the upper box's sides in a concave valley. (Disabled
// before because the lower box's top under the upper box, which no camera sees, was sampled.)
TEST(SegmentConvexity, ABoxOnABoxComesApart) {
  const Split s = split({synth::make_solid(synth::ShapeKind::box, {4, 3, 1}, at(0, 0, 0.5)),
                         synth::make_solid(synth::ShapeKind::box, {2, 1.5, 1}, at(0.3, 0.2, 1.5))},
                        20000, 5, Eigen::Vector3d(3, -6, 7));
  ASSERT_EQ(s.segments, 2u);
  EXPECT_NE(s.owner[0], s.owner[1]);
  for (double p : s.purity) EXPECT_GT(p, 0.95);
}

// Two boxes of different heights side by side, touching: the taller one's side rises from the
// lower one's top in a valley.
// DISABLED (issue 10, left): the camera lies in the plane where the boxes touch, so the taller
// one's side is seen edge-on (no points) and their fronts are one plane: no concave junction is
// in view. The fronts grow one smooth patch, so no junction test (convexity, crease_overlap)
// sees them; separating them needs a cut through that patch along the lower box's top edge
// (CPC's planar cuts, Schoeler et al. 2015).
TEST(SegmentConvexity, DISABLED_TwoTouchingBoxesComeApart) {
  const Split s = split({synth::make_solid(synth::ShapeKind::box, {2, 2, 1}, at(0, 0, 0.5)),
                         synth::make_solid(synth::ShapeKind::box, {2, 2, 2}, at(2, 0, 1))},
                        20000, 7, Eigen::Vector3d(1, -7, 6));
  ASSERT_EQ(s.segments, 2u);
  EXPECT_NE(s.owner[0], s.owner[1]);
  for (double p : s.purity) EXPECT_GT(p, 0.95);
}

// Two spheres that touch: their surfaces meet at a point in a valley all round.
// DISABLED (issue 10, left): whole surfaces and no viewpoint. Normals pointing away from the
// centroid of both spheres turn inwards near the contact, where the valley is; carrying the
// orientation over the graph (Hoppe's propagation, tried) carries one sphere's into the other at
// the contact, where their normals are parallel, and split YCB cans and noisy clouds elsewhere.
// The crease and sliver rules of convex_segments hold in organized clouds only (they split star
// and plus prisms whose normals are turned outward from the centroid).
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
