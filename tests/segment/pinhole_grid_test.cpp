// A depth image without its grid (an export to PLY or XYZ): its pixels are recovered from the
// points' directions, exactly, rounded as a text export rounds them too; anything that is no
// camera image in raster order gives none.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "captured_scene.hpp"
#include "config/pipeline_config.hpp"
#include "segment/pinhole_grid.hpp"
#include "segment/segment_scene.hpp"

namespace cloudshape::segment {
namespace {

CapturedScene touching_boxes() {
  synth::SceneRecipe recipe;
  recipe.layout = synth::SceneLayout::touching;
  recipe.count = 3;
  recipe.seed = 2;
  synth::CaptureOptions options;
  options.width = 320;
  options.height = 240;
  return capture_points(recipe, options);
}

// Each recovered pixel is the camera's, moved by the same offset (the grid starts at the first
// column and row anything was seen in).
void expect_same_pixels(const GridLayout& camera, const GridLayout& recovered) {
  ASSERT_EQ(recovered.pixel.size(), camera.pixel.size());
  std::size_t first_row = camera.height, first_column = camera.width, last_row = 0, last_column = 0;
  for (std::uint32_t p : camera.pixel) {
    first_row = std::min<std::size_t>(first_row, p / camera.width);
    last_row = std::max<std::size_t>(last_row, p / camera.width);
    first_column = std::min<std::size_t>(first_column, p % camera.width);
    last_column = std::max<std::size_t>(last_column, p % camera.width);
  }
  EXPECT_EQ(recovered.width, last_column - first_column + 1);
  EXPECT_EQ(recovered.height, last_row - first_row + 1);
  std::size_t moved = 0;
  for (std::size_t i = 0; i < camera.pixel.size(); ++i) {
    const std::size_t row = camera.pixel[i] / camera.width - first_row;
    const std::size_t column = camera.pixel[i] % camera.width - first_column;
    moved += recovered.pixel[i] == row * recovered.width + column ? 0 : 1;
  }
  EXPECT_EQ(moved, 0u);
}

TEST(PinholeGrid, AGeneratedFramesPixelsComeBack) {
  const CapturedScene scene = touching_boxes();
  ASSERT_GT(scene.points.size(), 20000u);
  const auto grid = pinhole_grid(scene.points);
  ASSERT_TRUE(grid.has_value());
  EXPECT_TRUE(grid->organized());
  expect_same_pixels(scene.grid, *grid);
}

// An ASCII export (PCD, XYZ) with six significant digits, as printf's %g writes them.
TEST(PinholeGrid, SixSignificantDigitsKeepThePixels) {
  const CapturedScene scene = touching_boxes();
  PointList rounded = scene.points;
  char text[32];
  for (Point& p : rounded) {
    for (int k = 0; k < 3; ++k) {
      std::snprintf(text, sizeof text, "%g", p[k]);
      p[k] = std::strtod(text, nullptr);
    }
  }
  ASSERT_NE(rounded[0], scene.points[0]);
  const auto grid = pinhole_grid(rounded);
  ASSERT_TRUE(grid.has_value());
  expect_same_pixels(scene.grid, *grid);
}

// Flipped for display (y up, the camera looking along -z), or mirrored (columns against x).
TEST(PinholeGrid, AFlippedOrMirroredFrameKeepsItsPixels) {
  const CapturedScene scene = touching_boxes();
  PointList flipped = scene.points, mirrored = scene.points;
  for (Point& p : flipped) p = Point(p.x(), -p.y(), -p.z());
  for (Point& p : mirrored) p.x() = -p.x();
  for (const PointList* points : {&flipped, &mirrored}) {
    const auto grid = pinhole_grid(*points);
    ASSERT_TRUE(grid.has_value());
    expect_same_pixels(scene.grid, *grid);
  }
}

TEST(PinholeGrid, NoGridWhereThePointsAreNoCameraImageInRasterOrder) {
  const CapturedScene scene = touching_boxes();
  // Shuffled: the pixels do not increase.
  PointList shuffled = scene.points;
  std::mt19937_64 rng(5);
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  EXPECT_FALSE(pinhole_grid(shuffled).has_value());
  // One point behind the camera.
  PointList behind = scene.points;
  behind[behind.size() / 2].z() = -behind[behind.size() / 2].z();
  EXPECT_FALSE(pinhole_grid(behind).has_value());
  // Every point moved by noise off its pixel's ray (a scan's points, a mesh's samples).
  PointList moved = scene.points;
  std::normal_distribution<double> noise(0.0, 0.002);
  for (Point& p : moved) p += Point(noise(rng), noise(rng), noise(rng));
  EXPECT_FALSE(pinhole_grid(moved).has_value());
  // One point off its ray by a third of a pixel.
  PointList one_off = scene.points;
  Point& p = one_off[one_off.size() / 3];
  const double columns =
      static_cast<double>(scene.grid.pixel[1]) - static_cast<double>(scene.grid.pixel[0]);
  ASSERT_TRUE(columns > 0.0 && columns < static_cast<double>(scene.grid.width))
      << "the first two points share a row";
  const double step =
      (scene.points[1].x() / scene.points[1].z() - scene.points[0].x() / scene.points[0].z()) /
      columns;
  p.x() += step * p.z() / 3.0;
  EXPECT_FALSE(pinhole_grid(one_off).has_value());
  // Too few points to read a lattice from; the points of one row.
  EXPECT_FALSE(
      pinhole_grid(PointList(scene.points.begin(), scene.points.begin() + 10)).has_value());
  PointList row;
  for (int i = 0; i < 100; ++i) row.emplace_back(0.01 * i, 0.0, 1.0);
  EXPECT_FALSE(pinhole_grid(row).has_value());
  EXPECT_FALSE(pinhole_grid({}).has_value());
}

// Segmented without its grid, the frame gives the objects it gives with it.
TEST(PinholeGrid, AFrameWithoutItsGridIsSegmentedAsWithIt) {
  const CapturedScene scene = touching_boxes();
  const config::SegmentConfig cfg = config::PipelineConfig{}.segment;
  const SceneSegmentation with = segment_scene(scene.points, scene.grid, cfg);
  const SceneSegmentation without = segment_scene(scene.points, GridLayout{}, cfg);
  ASSERT_GE(with.objects.size(), 3u);
  EXPECT_EQ(without.objects.size(), with.objects.size());
  EXPECT_TRUE(without.viewpoint.has_value());
}

}  // namespace
}  // namespace cloudshape::segment
