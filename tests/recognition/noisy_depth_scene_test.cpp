// Generated table scenes whose depth carries a Kinect's noise drawn independently for each pixel
// (cloudshape-synth scene --depth-noise 0.0019: 2.7 mm at 1.2 m, more than the 2 mm between
// pixels there): balls of 7-9 cm stay spheres, cones seen to their tip stay cones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "config/pipeline_config.hpp"
#include "kinect_faults.hpp"
#include "pipeline/recognize.hpp"
#include "report_of_label.hpp"
#include "synth/ground_truth.hpp"
#include "synth/scene_capture.hpp"

namespace cloudshape {
namespace {

// A generated frame of three solids as the recogniser takes it: its finite points on their pixels,
// and each point's label.
struct NoisyFrame {
  synth::SceneCapture capture;
  PointList points;
  GridLayout grid;
  std::vector<std::uint32_t> labels;
};

NoisyFrame noisy_frame(synth::SceneLayout layout, std::uint64_t seed,
                       const synth::CaptureOptions& options, std::uint32_t count = 3) {
  synth::SceneRecipe recipe;
  recipe.layout = layout;
  recipe.count = count;
  recipe.seed = seed;
  NoisyFrame frame{synth::capture_scene(recipe, options), {}, {}, {}};
  const synth::RangeImage& image = frame.capture.image;
  frame.grid = GridLayout{image.width, image.height, {}};
  for (std::size_t i = 0; i < image.points.size(); ++i) {
    if (!image.points[i].allFinite()) continue;
    frame.points.push_back(image.points[i]);
    frame.grid.pixel.push_back(static_cast<std::uint32_t>(i));
    frame.labels.push_back(image.labels[i]);
  }
  return frame;
}

using testing::kinect_faults;

// The Kinect's faults at twice its depth noise (`--depth-noise 0.004`).
synth::CaptureOptions twice_the_noise() {
  synth::CaptureOptions options = kinect_faults();
  options.depth_noise = 0.004;
  return options;
}

// The points as a PCD file stores them (float), as cloudshape-bench --scenes reads the frames.
NoisyFrame stored_frame(synth::SceneLayout layout, std::uint64_t seed,
                        const synth::CaptureOptions& options, std::uint32_t count) {
  NoisyFrame frame = noisy_frame(layout, seed, options, count);
  for (Point& p : frame.points) p = p.cast<float>().cast<double>();
  return frame;
}

// A labelled solid of a frame and the report standing for it: the one holding most of its points
// (none where no report holds any).
struct Holding {
  std::string where;  // "frame k, label l", for a trace
  synth::SceneObject object;
  std::optional<pipeline::ObjectResult> report;
};

// Every solid of the frames, of `kind` only where given, with its report.
std::vector<Holding> holdings(const std::vector<NoisyFrame>& frames,
                              const config::PipelineConfig& cfg,
                              std::optional<synth::ShapeKind> kind = std::nullopt) {
  std::vector<Holding> out;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const NoisyFrame& frame = frames[k];
    const auto result = pipeline::recognize_cloud(frame.points, frame.grid, cfg, "noisy frame");
    for (const synth::SceneObject& object : frame.capture.scene.objects) {
      if (kind && object.solid.kind != *kind) continue;
      const pipeline::ObjectResult* holder =
          testing::report_of_label(result.objects, frame.labels, object.label);
      out.push_back({"frame " + std::to_string(k) + ", label " + std::to_string(object.label),
                     object,
                     holder ? std::optional<pipeline::ObjectResult>(*holder) : std::nullopt});
    }
  }
  return out;
}

// The shape named for the solid of `label` in the frames ("missed" where no report holds it).
std::string name_of(const std::vector<NoisyFrame>& frames, const config::PipelineConfig& cfg,
                    std::uint32_t label) {
  for (const Holding& h : holdings(frames, cfg))
    if (h.object.label == label) return h.report ? h.report->shape : std::string("missed");
  return "no such label";
}

// Each cone of the frames named a cone, its radius within `radius_share` of the truth and its
// height from `short_share` under to `long_share` over it.
void expect_cones(const std::vector<Holding>& cones, double radius_share, double short_share,
                  double long_share) {
  for (const Holding& h : cones) {
    SCOPED_TRACE(h.where);
    ASSERT_TRUE(h.report.has_value());
    EXPECT_EQ(h.report->shape, "cone");
    if (h.report->shape != "cone") continue;
    const double radius = synth::dimension(h.object.solid, "radius");
    const double height = synth::dimension(h.object.solid, "height");
    EXPECT_NEAR(h.report->dimensions[0].second, radius, radius_share * radius);
    EXPECT_GE(h.report->dimensions[1].second, (1.0 - short_share) * height);
    EXPECT_LE(h.report->dimensions[1].second, (1.0 + long_share) * height);
  }
}

// ... radius and height within `share` of the truth.
void expect_cones(const std::vector<Holding>& cones, double share) {
  expect_cones(cones, share, share, share);
}

// Random layout, seeds 2, 4, 6 and 9: five balls of radius 35-46 mm, 1.1-1.5 m off, their points
// 3-8% of their radius apart in noise. A band of a few resolutions about a surface was narrower
// than that noise and selected the points that happened to lie flat: a plane through a ball's cap
// passed for a lid, so no sphere was tried: two balls were frusta and one a cylinder. Each object's
// resolution is now no finer than three times its points' noise where the pixels are noisy on their
// own (preprocess.noise_resolution): every ball, judged by the report holding most of its points,
// is a sphere, its radius within 10%.
TEST(NoisyDepthScene, BallsStaySpheres) {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  synth::CaptureOptions options;
  options.depth_noise = 0.0019;
  std::vector<NoisyFrame> frames;
  for (std::uint64_t seed : {2, 4, 6, 9})
    frames.push_back(noisy_frame(synth::SceneLayout::random, seed, options));
  const std::vector<Holding> balls = holdings(frames, cfg, synth::ShapeKind::sphere);
  for (const Holding& h : balls) {
    SCOPED_TRACE(h.where);
    ASSERT_TRUE(h.report.has_value());
    EXPECT_EQ(h.report->shape, "sphere");
    if (h.report->shape != "sphere") continue;
    const double radius = synth::dimension(h.object.solid, "radius");
    EXPECT_NEAR(h.report->dimensions.front().second, radius, 0.1 * radius);
  }
  EXPECT_EQ(balls.size(), 5u);
}

// The cones of seven such frames with the Kinect's other faults too (`--quantize --shadows
// --flying-pixels 0.5`): random 1 and 2, row 6, wall 3, 4, 5 and 7, 1.0-1.4 m off, radius 41-80
// mm, 1 200-5 400 points, the noise 2-5% of their radius. Their tangent planes scatter and met far
// from the apex (cones half a metre wide, or none), the base-free fits explained 42-66% of the
// points, and the eight were named cylinders (5) or boxes (3); on two of them the noisy rim made
// the key-points say tetrahedron, whose own fit then failed. Each cone's side is now also
// fitted to the points alone (the frustum's side fit) and closed at the apex it implies
// (fit_cone_from_side), where the points reach within solve.apex_gap of that apex, unless the
// key-points' polyhedron was fitted. Measured: every one a cone, radius within 8%, height within
// 12% (the longest: its tip region thin and noisy); tolerance 20%.
TEST(NoisyDepthScene, ConesSeenToTheirTipStayCones) {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  std::vector<NoisyFrame> frames;
  for (const auto& [layout, seed] :
       {std::pair{synth::SceneLayout::random, 1}, std::pair{synth::SceneLayout::random, 2},
        std::pair{synth::SceneLayout::row, 6}, std::pair{synth::SceneLayout::wall, 3},
        std::pair{synth::SceneLayout::wall, 4}, std::pair{synth::SceneLayout::wall, 5},
        std::pair{synth::SceneLayout::wall, 7}})
    frames.push_back(noisy_frame(layout, static_cast<std::uint64_t>(seed), kinect_faults()));
  const std::vector<Holding> cones = holdings(frames, cfg, synth::ShapeKind::cone);
  expect_cones(cones, 0.2);
  EXPECT_EQ(cones.size(), 8u);
}

// Stacked layout, seed 9, with the Kinect's faults as above: three boxes stacked, each turned on
// the one below, 0.9-1.0 m off. The upper boxes' front faces are nearly parallel to the faces below
// them and touch them at a corner, where the top between them narrows to nothing: their normals
// grew into one smooth patch over all three boxes, and the three came out as one object (no solid
// fitted). A patch of offset flat pieces is now split into them (segment.piece_*), and the pieces
// meet along a few edges only: every box its own object, named box, each dimension within 12 mm
// (measured: at most 9 mm off, the 89 mm side of the middle box; the top box's 33 mm height 40).
TEST(NoisyDepthScene, BoxesStackedTurnedComeApart) {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const synth::CaptureOptions options = kinect_faults();
  const NoisyFrame frame = noisy_frame(synth::SceneLayout::stacked, 9, options);
  const auto result = pipeline::recognize_cloud(frame.points, frame.grid, cfg, "stacked boxes");
  std::vector<const pipeline::ObjectResult*> holders;
  for (const synth::SceneObject& object : frame.capture.scene.objects) {
    SCOPED_TRACE("label " + std::to_string(object.label));
    const pipeline::ObjectResult* holder =
        testing::report_of_label(result.objects, frame.labels, object.label);
    ASSERT_NE(holder, nullptr);
    EXPECT_EQ(holder->shape, "box");
    for (const pipeline::ObjectResult* other : holders) EXPECT_NE(holder, other);
    holders.push_back(holder);
    if (holder->shape != "box") continue;
    std::vector<double> truth{synth::dimension(object.solid, "length"),
                              synth::dimension(object.solid, "width"),
                              synth::dimension(object.solid, "height")};
    std::vector<double> found;
    for (const auto& d : holder->dimensions) found.push_back(d.second);
    std::sort(truth.begin(), truth.end());
    std::sort(found.begin(), found.end());
    ASSERT_EQ(found.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(found[k], truth[k], 0.012) << k;
  }
  EXPECT_EQ(holders.size(), 3u);
}

// How the objects of frames come out: named their own shape, named another, unknown.
struct Names {
  int right = 0, wrong = 0, unknown = 0,
      alike = 0;  // alike: unknown as two solids explain it alike
};

Names names_of(const std::vector<NoisyFrame>& frames, const config::PipelineConfig& cfg) {
  Names out;
  for (const NoisyFrame& frame : frames) {
    const auto result = pipeline::recognize_cloud(frame.points, frame.grid, cfg, "four solids");
    for (const synth::SceneObject& object : frame.capture.scene.objects) {
      const pipeline::ObjectResult* holder =
          testing::report_of_label(result.objects, frame.labels, object.label);
      if (holder == nullptr) continue;
      if (holder->shape == "unknown") {
        ++out.unknown;
        out.alike += holder->reason.find("explain the points alike") != std::string::npos;
      } else if (holder->shape == synth::to_string(object.solid.kind)) {
        ++out.right;
      } else {
        ++out.wrong;
      }
    }
  }
  return out;
}

// Random and row layouts, seeds 1-10, with twice the Kinect's noise (`--depth-noise 0.004`, its
// other faults too), and row seed 18 with four solids and the Kinect's own: small solids 1.3-1.8 m
// off whose noise is a sixth to a tenth of their size. Six of the 18 named another solid (among
// them balls and a pentagonal prism named cylinders, a cone a box) were so where a solid of another
// family explained as many points as closely, and the key-points, finding no polyhedron's corners,
// gave only a view's border ("cylinder") to break the tie. Such an object is now unknown
// (solve.ambiguity_rms_ratio): those six, and none of the 40 named right. Nor do a polyhedron's
// corners break the tie where that polyhedron's own solid was not fitted: random seed 12 of the
// four-object frames, a 3.6 cm ball 1.7 m off whose noisy rim gave a tetrahedron's four corners,
// named a cylinder while a sphere explained its points alike, is the seventh; the right ones of
// that frame stay. The eighth, row seed 2's cone lying with its tip lost, a cylinder and a frustum
// alike (ConesATiltedCylinderFollowsAreNotNamedCylinders). Since the planes' band follows the noise
// read along the rays (planes.noise_sigmas) the faces of those frames no longer come apart in
// layers and most of those eight are told apart: 55 objects named right with the rule or without
// it, two alike (`unknown`), which without it are two of six wrong names.
TEST(NoisyDepthScene, SolidsThePointsDoNotTellApartAreNotNamed) {
  auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const synth::CaptureOptions twice = twice_the_noise();
  std::vector<NoisyFrame> frames;
  for (synth::SceneLayout layout : {synth::SceneLayout::random, synth::SceneLayout::row})
    for (std::uint64_t seed = 1; seed <= 10; ++seed)
      frames.push_back(stored_frame(layout, seed, twice, 3));
  frames.push_back(stored_frame(synth::SceneLayout::row, 18, kinect_faults(), 4));
  frames.push_back(stored_frame(synth::SceneLayout::random, 12, kinect_faults(), 4));
  const Names with = names_of(frames, cfg);
  cfg.solve.ambiguity_rms_ratio = 0.0;
  const Names without = names_of(frames, cfg);
  EXPECT_EQ(without.alike, 0);
  EXPECT_EQ(with.alike, 2);
  EXPECT_EQ(with.wrong, without.wrong - 2);
  EXPECT_EQ(with.right, without.right);
  EXPECT_GE(with.right, 55);
}

// Cones whose fits from their normals missed the apex, so that they explained 71-88% of the points
// where a cylinder explained 81-99% of them within the tolerance (two resolutions, each at least
// three times the noise): twice the Kinect's noise, random 10 and row 8 (three solids); the
// Kinect's own, wall 12 and 14 (four solids). The side fitted to the points alone was tried only
// where the cone explained under solve.side_fit_min_inlier_fraction, and all four were named
// cylinders. It is now tried also where the cone explains solve.min_inlier_fraction but is out of
// the running (more than solve.preferred_margin below the most explained), and explains 98-100%:
// measured, every one a cone, radius within 10% and height within 7%; tolerance 15%. Row 8's
// (twice the noise) was `unknown` while the planes' band followed the noise along the rays (a
// plane within that noise explained 79% of its points, the cone 75%), until cones and frusta whose
// points stop short of their rim dropped out (solve.tapered_min_rim_reach): a cone again, radius
// 4.7% short, height 3.7% long.
TEST(NoisyDepthScene, ConesOutOfTheRunningGetTheirSideFitted) {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const synth::CaptureOptions twice = twice_the_noise();
  const std::vector<NoisyFrame> frames = {
      stored_frame(synth::SceneLayout::random, 10, twice, 3),
      stored_frame(synth::SceneLayout::row, 8, twice, 3),
      stored_frame(synth::SceneLayout::wall, 12, kinect_faults(), 4),
      stored_frame(synth::SceneLayout::wall, 14, kinect_faults(), 4)};
  const std::vector<Holding> cones = holdings(frames, cfg, synth::ShapeKind::cone);
  ASSERT_EQ(cones.size(), 4u);
  expect_cones(cones, 0.15);
}

// The Kinect's faults, random layout seed 15 (four solids): a cone 1.84 m off seen base-on, its
// disc alone, its depth 6.3 mm off along the rays, more than the pixels' 3.5 mm spacing. The
// resolution the points' nearest neighbours read (2-3 mm of noise) left bands narrower than the
// noise, the plane fits took the disc apart in layers and a cylinder 4 cm high held them as its
// caps and recessed lids, 91% of the points: named a cylinder at confidence 0.9. The disc's plane
// now takes the points within solve.flat_noise_sigmas of the noise read along the rays (6.1 mm):
// 98% of them, more than the cylinder explains, so no curvature is measured: `unknown`. The
// frame's tetrahedron is still named.
TEST(NoisyDepthScene, ADiscSeenThroughItsNoiseIsNoCylinder) {
  auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const std::vector<NoisyFrame> frames = {
      stored_frame(synth::SceneLayout::random, 15, kinect_faults(), 4)};
  ASSERT_EQ(frames.front().capture.scene.objects.front().solid.kind, synth::ShapeKind::cone);
  const std::uint32_t disc = frames.front().capture.scene.objects.front().label;
  EXPECT_EQ(name_of(frames, cfg, disc), "unknown");
  EXPECT_EQ(name_of(frames, cfg, frames.front().capture.scene.objects.back().label), "tetrahedron");
  cfg.solve.flat_noise_sigmas = 0.0;
  EXPECT_EQ(name_of(frames, cfg, disc), "cylinder");
}

// Twice the Kinect's noise (0.0038, its other faults too), row 5: the tetrahedron 1.4 m off shows
// one face square to the sensor, its outline within a circle, and a cylinder 3 cm tall held it as
// a cap with 0.3% of the points on its side (explaining 99%, confidence 0.61). A cylinder's radius
// and axis are its side's: it is claimed only where solve.cylinder_min_side_share (5%) of the
// points lie on the side. Measured: `unknown`; a cylinder with the rule off.
TEST(NoisyDepthScene, AFaceACapsCircleHoldsIsNoCylinder) {
  auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  synth::CaptureOptions options = kinect_faults();
  options.depth_noise = 0.0038;
  const std::vector<NoisyFrame> frames = {stored_frame(synth::SceneLayout::row, 5, options, 3)};
  std::optional<std::uint32_t> tetrahedron;
  for (const synth::SceneObject& object : frames.front().capture.scene.objects)
    if (object.solid.kind == synth::ShapeKind::tetrahedron) tetrahedron = object.label;
  ASSERT_TRUE(tetrahedron.has_value());
  const std::string named = name_of(frames, cfg, *tetrahedron);
  EXPECT_TRUE(named == "unknown" || named == "tetrahedron") << named;
  cfg.solve.cylinder_min_side_share = 0.0;
  EXPECT_EQ(name_of(frames, cfg, *tetrahedron), "cylinder");
}

// Twice the Kinect's noise (its other faults too), random 6 and row 1: four balls of radius 35-77
// mm 1.3-1.6 m off. A band of a few resolutions about a plane held a ball's cap, and its outline
// read as a circular face: a lid, for which only the cylinder, cone, frustum and other prisms were
// tried, and three of the balls were named frusta (row 1's other, `unknown`). The sphere is now
// tried beside such a face too in a view (a sensor's viewpoint known): measured, those three
// spheres, radius within 9%, centre within 6 mm (tolerance 12%, 10 mm); the fourth, `unknown`
// while the planes' band was narrower than the noise, is a sphere too since it follows the noise
// along the rays (planes.noise_sigmas). None named another solid.
TEST(NoisyDepthScene, BallsWhoseCapPassesForALidStaySpheres) {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const synth::CaptureOptions twice = twice_the_noise();
  const std::vector<NoisyFrame> frames = {stored_frame(synth::SceneLayout::random, 6, twice, 3),
                                          stored_frame(synth::SceneLayout::row, 1, twice, 3)};
  const std::vector<Holding> balls = holdings(frames, cfg, synth::ShapeKind::sphere);
  int spheres = 0;
  for (const Holding& h : balls) {
    SCOPED_TRACE(h.where);
    ASSERT_TRUE(h.report.has_value());
    EXPECT_TRUE(h.report->shape == "sphere" || h.report->shape == "unknown") << h.report->shape;
    if (h.report->shape != "sphere") continue;
    ++spheres;
    const double radius = synth::dimension(h.object.solid, "radius");
    EXPECT_NEAR(h.report->dimensions.front().second, radius, 0.12 * radius);
    EXPECT_LT((h.report->center - h.object.solid.pose.center).norm(), 0.01);
  }
  EXPECT_EQ(balls.size(), 4u);
  EXPECT_EQ(spheres, 4);
}

// A pentagonal prism's cap outline, its corners each placed within the verification's tolerance
// (two resolutions, each at least three noises under a depth camera's noise), strays from a
// regular pentagon by more than solve.regular_tolerance (3%) of its side: random seed 11 of the
// four-object frames (the Kinect's faults; sides 61-75 mm, 7 cm prism 1.3 m off) and random seed 3
// at twice the noise. Both pentagons were taken for an irregular prism's and named "prism" with
// five sides. A side may now stray by the corners' tolerance too: neither is another prism. Both
// were `unknown` (the pentagonal prism's own fit failed: its hidden sides placed where all of the
// points end, 8-16 mm out in the noise, so the pentagon was too large for its cap); with the hidden
// sides where the seen sides' own points end both are pentagonal prisms (sides within 2%), and the
// four other objects named right stay so.
TEST(NoisyDepthScene, PentagonsRegularWithinTheNoiseAreNoOtherPrism) {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const synth::CaptureOptions twice = twice_the_noise();
  const std::vector<NoisyFrame> frames = {
      stored_frame(synth::SceneLayout::random, 11, kinect_faults(), 4),
      stored_frame(synth::SceneLayout::random, 3, twice, 3)};
  int pentagonal = 0, right = 0;
  for (const Holding& h : holdings(frames, cfg)) {
    SCOPED_TRACE(h.where);
    ASSERT_TRUE(h.report.has_value());
    right += h.report->shape == synth::to_string(h.object.solid.kind);
    if (h.object.solid.kind != synth::ShapeKind::pentagonal_prism) continue;
    ++pentagonal;
    EXPECT_NE(h.report->shape, "prism");
  }
  EXPECT_EQ(pentagonal, 3);
  EXPECT_EQ(right, 6);
}

// Pentagonal prisms lying on a side under the Kinect's faults, seen on their cap and the two sides
// meeting at the top (108 deg): row seed 6 (three solids; side 51 mm, 1.3 m off) and row seed 14
// (four solids; sides 50-61 mm, 1.5-1.8 m off). A pentagonal prism's hidden sides were placed where
// all of the points end along their normals: depth noise and flying pixels at the silhouette
// reach 3-17 mm beyond the edge, the pentagon came out 7-30% too large, its cap then filled under
// solve.cap_section_fill of it and the fit failed, and the two with a box's third face in view (the
// cap, square to both sides) were named boxes: the second side, 18 deg off a box axis, passes
// solve.stray_face_degrees. The hidden sides now lie where the seen sides' own points end:
// measured, those two and row 14's other seen on two sides are pentagonal prisms, sides within 3%
// (tolerance 6%), none a box, and the other objects named right stay so. The two seen end to end
// were 10-18% long where the points' end along the axis gave their open end; where the seen sides'
// own points end, within 2% (tolerance 5%; row 14's third is partly hidden: 18% short).
TEST(NoisyDepthScene, PentagonalPrismsSeenOnTwoSidesAreNoBoxes) {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const std::vector<NoisyFrame> frames = {
      stored_frame(synth::SceneLayout::row, 6, kinect_faults(), 3),
      stored_frame(synth::SceneLayout::row, 14, kinect_faults(), 4)};
  const std::vector<std::string> whole = {"frame 0, label 40", "frame 1, label 50"};
  int named = 0, right = 0;
  for (const Holding& h : holdings(frames, cfg)) {
    SCOPED_TRACE(h.where);
    ASSERT_TRUE(h.report.has_value());
    if (h.object.solid.kind != synth::ShapeKind::pentagonal_prism) {
      right += h.report->shape == synth::to_string(h.object.solid.kind);
      continue;
    }
    EXPECT_NE(h.report->shape, "box");
    if (h.report->shape != "pentagonal_prism") continue;
    ++named;
    const double side = synth::dimension(h.object.solid, "side");
    EXPECT_NEAR(h.report->dimensions.front().second, side, 0.06 * side);
    if (std::find(whole.begin(), whole.end(), h.where) == whole.end()) continue;
    const double height = synth::dimension(h.object.solid, "height");
    EXPECT_NEAR(h.report->dimensions[1].second, height, 0.05 * height);
  }
  EXPECT_EQ(named, 3);
  EXPECT_EQ(right, 3);
}

// Objects whose points a plane explains as well as the round solid chosen for them: one face of a
// tetrahedron, or a cone's base, seen under a depth camera's noise. The Kinect's faults: row seed 5
// (an 8.8 cm tetrahedron 1.4 m off, named a cylinder 3.7 cm tall) and wall seed 6 (a cone's base 1
// m off, named a cylinder 4 mm tall); with four solids, random seed 17 (a tetrahedron's face taken
// for a flat cone's hollow, so for a container: a cylinder 2.3 cm tall at 0.96) and row seed 12 (a
// tetrahedron named a cylinder 11 cm wide). The curvature such a solid claims is within the
// tolerance of a plane: the four are now unknown ("a plane explains the points as well"), and the
// seven objects of those frames named right stay so. Since the planes' band follows the noise along
// the rays (planes.noise_sigmas), random seed 17's face, one plane now, fits no solid at all
// (`unknown`, "no solid could be fitted"), and that frame's ball, a cylinder before, is a sphere:
// eight right. Since a cylinder needs solve.cylinder_min_side_share of the points on its side,
// the three other faces fit no solid either (their cylinders' sides held a few percent); with that
// rule off, a plane explains them as well as before.
TEST(NoisyDepthScene, RoundSolidsAPlaneExplainsAsWellAreNotNamed) {
  auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const std::vector<NoisyFrame> frames = {
      stored_frame(synth::SceneLayout::row, 5, kinect_faults(), 3),
      stored_frame(synth::SceneLayout::wall, 6, kinect_faults(), 3),
      stored_frame(synth::SceneLayout::random, 17, kinect_faults(), 4),
      stored_frame(synth::SceneLayout::row, 12, kinect_faults(), 4)};
  // The flat view's label in each frame, in order.
  const std::vector<std::string> flat = {"frame 0, label 30", "frame 1, label 20",
                                         "frame 2, label 20", "frame 3, label 50"};
  for (const double side_share : {cfg.solve.cylinder_min_side_share, 0.0}) {
    cfg.solve.cylinder_min_side_share = side_share;
    SCOPED_TRACE("cylinder_min_side_share " + std::to_string(side_share));
    int right = 0, flats = 0;
    for (const Holding& h : holdings(frames, cfg)) {
      SCOPED_TRACE(h.where);
      ASSERT_TRUE(h.report.has_value());
      right += h.report->shape == synth::to_string(h.object.solid.kind);
      if (std::find(flat.begin(), flat.end(), h.where) == flat.end()) continue;
      ++flats;
      EXPECT_EQ(h.report->shape, "unknown");
      const bool plane_rule = side_share == 0.0 && h.where != "frame 2, label 20";
      if (plane_rule)
        EXPECT_NE(h.report->reason.find("a plane explains the points as well"), std::string::npos)
            << h.report->reason;
      else
        EXPECT_EQ(h.report->reason, "no solid could be fitted");
    }
    EXPECT_EQ(flats, 4);
    EXPECT_EQ(right, 8);
  }
}

// Cones lying on the table with their tip lost, seen from the side: random seed 15 of the
// four-object frames (the Kinect's faults) and row seed 2 at twice its noise. A cylinder tilted to
// follow the near side explained 94-98% of the points within the tolerance, a frustum narrowing
// from 45 to 14 mm 95-100%; a cylinder and a frustum were one family, the cylinder the simpler
// answer, and both were named cylinders. A frustum whose side leans by more than
// solve.parallel_degrees and whose radii differ by more than two tolerances is now another answer
// than a cylinder: both unknown, and the three objects of those frames named right stay so
// (random 15's other cones are left: one seen nearly base-on, a cylinder; one a frustum).
TEST(NoisyDepthScene, ConesATiltedCylinderFollowsAreNotNamedCylinders) {
  auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const synth::CaptureOptions twice = twice_the_noise();
  const std::vector<NoisyFrame> frames = {
      stored_frame(synth::SceneLayout::random, 15, kinect_faults(), 4),
      stored_frame(synth::SceneLayout::row, 2, twice, 3)};
  const std::vector<std::string> lying = {"frame 0, label 40", "frame 1, label 20"};
  const auto lying_names = [&](const std::vector<Holding>& all, int& right) {
    std::vector<std::string> names;
    right = 0;
    for (const Holding& h : all) {
      SCOPED_TRACE(h.where);
      EXPECT_TRUE(h.report.has_value());
      if (!h.report) continue;
      if (std::find(lying.begin(), lying.end(), h.where) != lying.end()) {
        names.push_back(h.report->shape);
        if (h.report->shape == "unknown") {
          EXPECT_NE(h.report->reason.find("a cylinder and a frustum explain the points alike"),
                    std::string::npos)
              << h.report->reason;
        }
      } else {
        right += h.report->shape == synth::to_string(h.object.solid.kind);
      }
    }
    return names;
  };
  int right = 0, right_without = 0;
  const std::vector<std::string> with = lying_names(holdings(frames, cfg), right);
  cfg.solve.ambiguity_rms_ratio = 0.0;
  const std::vector<std::string> without = lying_names(holdings(frames, cfg), right_without);
  EXPECT_EQ(with, std::vector<std::string>(2, "unknown"));
  EXPECT_EQ(without, std::vector<std::string>(2, "cylinder"));
  EXPECT_EQ(right, 3);
  EXPECT_EQ(right_without, right);
}

// Cones whose tip the segmentation lost under the Kinect's faults: row seeds 9 and 2 (three
// solids), row 16 and wall 18 (four solids), and row 6 at twice the noise. The points about a
// tip lie off the axis on every side, the side fitted through them ends in a top of 8-12 mm
// (about the tolerance), and the three seen to that top were named frusta (row 2 and wall 18
// unknown: a tilted cylinder explained them alike). The cone that frustum's side comes to is now
// the cone's fit too, where the points reach within solve.apex_gap of its apex: measured, every one
// a cone, radius within 7%, height 3-21% long (the side's slope follows the tip's points);
// tolerances 10% and 25%.
TEST(NoisyDepthScene, ConesWhoseTipIsLostAreNoFrusta) {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const synth::CaptureOptions twice = twice_the_noise();
  const std::vector<NoisyFrame> frames = {
      stored_frame(synth::SceneLayout::row, 9, kinect_faults(), 3),
      stored_frame(synth::SceneLayout::row, 2, kinect_faults(), 3),
      stored_frame(synth::SceneLayout::row, 16, kinect_faults(), 4),
      stored_frame(synth::SceneLayout::wall, 18, kinect_faults(), 4),
      stored_frame(synth::SceneLayout::row, 6, twice, 3)};
  const std::vector<Holding> cones = holdings(frames, cfg, synth::ShapeKind::cone);
  EXPECT_EQ(cones.size(), 6u);  // row 9 holds two
  expect_cones(cones, 0.1, 0.1, 0.25);
}

}  // namespace
}  // namespace cloudshape
