// io::decimated: an organized cloud at a lower resolution keeps the points on every step-th pixel
// of every step-th row, with their labels, on the smaller grid.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "io/cloud_decimate.hpp"

namespace cloudshape::io {
namespace {

// A 5 x 3 image with pixel (column, row) at (column, row, 1) labelled 10 * row + column, pixel
// (2, 2) empty (no return there).
CloudFile five_by_three() {
  CloudFile cloud;
  cloud.format = "pcd-binary";
  cloud.grid.width = 5;
  cloud.grid.height = 3;
  for (std::uint32_t row = 0; row < 3; ++row) {
    for (std::uint32_t column = 0; column < 5; ++column) {
      if (row == 2 && column == 2) continue;
      cloud.points.emplace_back(column, row, 1.0);
      cloud.labels.push_back(10 * row + column);
      cloud.grid.pixel.push_back(row * 5 + column);
    }
  }
  return cloud;
}

TEST(IoCloudDecimate, KeepsEveryOtherPixelOfEveryOtherRowOnTheSmallerGrid) {
  const CloudFile out = decimated(five_by_three(), 2);
  EXPECT_EQ(out.format, "pcd-binary");
  EXPECT_EQ(out.grid.width, 3u);   // columns 0, 2, 4
  EXPECT_EQ(out.grid.height, 2u);  // rows 0, 2
  EXPECT_TRUE(out.grid.organized());
  // Row 0: columns 0, 2, 4; row 2: columns 0 and 4 (2 is empty).
  const std::vector<std::uint32_t> labels{0, 2, 4, 20, 24};
  const std::vector<std::uint32_t> pixels{0, 1, 2, 3, 5};
  EXPECT_EQ(out.labels, labels);
  EXPECT_EQ(out.grid.pixel, pixels);
  ASSERT_EQ(out.points.size(), 5u);
  EXPECT_EQ(out.points[4], Point(4.0, 2.0, 1.0));
}

TEST(IoCloudDecimate, AStepOfOneIsACopyAndUnlabelledCloudsStayUnlabelled) {
  const CloudFile cloud = five_by_three();
  const CloudFile same = decimated(cloud, 1);
  EXPECT_EQ(same.points, cloud.points);
  EXPECT_EQ(same.labels, cloud.labels);
  EXPECT_EQ(same.grid.pixel, cloud.grid.pixel);
  EXPECT_EQ(same.grid.width, cloud.grid.width);
  CloudFile unlabelled = cloud;
  unlabelled.labels.clear();
  const CloudFile out = decimated(unlabelled, 3);
  EXPECT_TRUE(out.labels.empty());
  EXPECT_EQ(out.grid.width, 2u);   // columns 0, 3
  EXPECT_EQ(out.grid.height, 1u);  // row 0
  EXPECT_EQ(out.points.size(), 2u);
}

}  // namespace
}  // namespace cloudshape::io
