// The label text beside each drawn solid.
#include <gtest/gtest.h>

#include "render/label.hpp"

namespace cloudshape::render {
namespace {

TEST(Label, NamesTheShapeItsDimensionsAndConfidence) {
  pipeline::ObjectResult box;
  box.shape = "box";
  box.dimensions = {{"length", 0.30123}, {"width", 0.2009}, {"height", 0.1}};
  box.confidence = 0.968;
  EXPECT_EQ(object_label(box, 1), "1 box  l 0.301  w 0.201  h 0.1  97%");
  EXPECT_EQ(object_tag(box, 1), "1 box");

  pipeline::ObjectResult prism;
  prism.shape = "pentagonal_prism";
  prism.dimensions = {{"side", 31.25}, {"height", 120.0}};
  prism.confidence = 0.5;
  prism.partial = true;
  EXPECT_EQ(object_label(prism, 3), "3 pentagonal prism  side 31.2  h 120  partial 50%");
}

TEST(Label, AnUnknownObjectSaysWhy) {
  pipeline::ObjectResult o;
  o.reason = "all points coplanar";
  EXPECT_EQ(object_label(o, 2), "2 unknown  (all points coplanar)");
}

}  // namespace
}  // namespace cloudshape::render
