// Draws a recognised cloud with Cairo (no display needed) and writes it as a PNG: the points,
// each solid's wireframe and label, in the panels plan_picture() lays out.
#pragma once

#include <stdexcept>
#include <string>

#include "geometry/point_cloud.hpp"
#include "pipeline/result.hpp"
#include "render/picture_plan.hpp"

namespace cloudshape::render {

// A picture that could not be made or written; what() names the file and the problem.
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `points` and `grid` are the cloud the result was recognised from (its objects'
// point_indices index `points`). Throws RenderError.
void write_picture_png(const PointList& points, const GridLayout& grid,
                       const pipeline::RecognitionResult& result, const std::string& png_path,
                       const RenderOptions& options = {});

}  // namespace cloudshape::render
