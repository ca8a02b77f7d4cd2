// What a picture of one recognised cloud shows, before anything is drawn: its panels (the
// sensor's or principal-axes view beside an oblique one), their cameras and the wireframes.
#pragma once

#include <string>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "pipeline/result.hpp"
#include "render/view.hpp"
#include "render/wireframe.hpp"

namespace cloudshape::render {

struct RenderOptions {
  int width = 1200;
  int height = 800;
};

struct Panel {
  std::string caption;
  PixelRect rect;
  View view;
  std::vector<Wireframe> wireframes;  // one per result object, as seen from this panel's camera
};

struct PicturePlan {
  int width = 0;
  int height = 0;
  PixelRect header;   // the cloud's name and counts
  PixelRect legend;   // one full label per object, in legend_columns columns
  int legend_columns = 2;
  std::size_t legend_rows = 0;  // objects beyond columns x rows are counted, not listed
  std::vector<Panel> panels;  // left to right, below the legend
};

inline constexpr double kLegendRowHeight = 20.0;

// An organized cloud (a depth camera's grid) is first seen from its sensor: the camera at the
// origin looking along +z. Any other cloud is seen along its principal axes (cameras.hpp), from
// the side its solids were seen from (the seen points lie between the sensor and each solid's centre).
// The second panel looks at the objects' points from 40 degrees right and 30 degrees above.
PicturePlan plan_picture(const PointList& points, const GridLayout& grid,
                         const pipeline::RecognitionResult& result, const RenderOptions& options = {});

}  // namespace cloudshape::render
