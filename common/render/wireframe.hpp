// The wireframe of a recognised solid in world coordinates: polylines along its edges, rims
// and silhouettes, from its shape, dimensions and pose as INTERFACE.md defines them.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "pipeline/result.hpp"

namespace cloudshape::render {

struct Polyline {
  std::vector<Eigen::Vector3d> points;
  bool closed = false;   // the last point joins the first
  bool outline = false;  // the solid's silhouette from this view: never behind its own surface
};

struct Wireframe {
  std::vector<Polyline> lines;  // empty: nothing to draw (unknown shape, missing dimension)
};

// `toward_viewer` is a unit vector from the solid towards the camera: a round solid's
// outline (a cylinder's or cone's side lines, a sphere's rim) depends on where it is seen from.
Wireframe solid_wireframe(const pipeline::ObjectResult& object, const Eigen::Vector3d& toward_viewer);

}  // namespace cloudshape::render
