// The words of a picture, drawn with Cairo: the header (file, points, objects), the legend of
// full labels, and each solid's tag in a panel, placed so that tags do not overlap.
#pragma once

#include <cairo.h>

#include <cstddef>

#include "geometry/point_cloud.hpp"
#include "pipeline/result.hpp"
#include "render/picture_plan.hpp"

namespace cloudshape::render {

void draw_header(cairo_t* cr, const PicturePlan& plan, const pipeline::RecognitionResult& result,
                 std::size_t points);

// Each object's full label, column by column, a swatch of its points' colour before it.
void draw_legend(cairo_t* cr, const PicturePlan& plan, const pipeline::RecognitionResult& result);

// "N shape" beside each solid in `panel`, with a leader to the top of its drawing.
void draw_tags(cairo_t* cr, const Panel& panel, const pipeline::RecognitionResult& result,
               const PointList& points);

}  // namespace cloudshape::render
