// Picture file names from a cloud's source.
#include <gtest/gtest.h>

#include "render/picture_name.hpp"

namespace cloudshape::render {
namespace {

TEST(PictureName, DropsAPlainExtensionAndKeepsAMessageIndex) {
  EXPECT_EQ(picture_stem("learn0.pcd"), "learn0");
  EXPECT_EQ(picture_stem("scan.v2.xyz"), "scan.v2");
  EXPECT_EQ(picture_stem("dir/sub/box.ply"), "box");
  EXPECT_EQ(picture_stem("rec.mcap#12"), "rec.mcap_12");
  EXPECT_EQ(picture_stem("a b:c.pcd"), "a_b_c");
  EXPECT_EQ(picture_stem(""), "cloud");
  EXPECT_EQ(picture_stem(".."), "cloud");
  EXPECT_EQ(picture_stem(".pcd"), ".pcd");
}

}  // namespace
}  // namespace cloudshape::render
