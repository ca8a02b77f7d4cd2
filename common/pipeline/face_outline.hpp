// The outline of one flat face in its own plane: a circle (a can's lid, a cup's bottom) or a
// rectangle (a box's face), told apart by how its convex hull fills its best circle and rectangle.
#pragma once

#include "geometry/point_cloud.hpp"
#include "pipeline/planes.hpp"

namespace cloudshape::pipeline {

enum class OutlineKind { undecided, circle, rectangle };

struct FaceOutline {
  OutlineKind kind = OutlineKind::undecided;
  Point center = Point::Zero();  // the fitted circle's centre, on the plane
  double radius = 0.0;           // the fitted circle's radius
  double circle_rms = 0.0;       // RMS radial residual of the hull outline, over the radius
  double rect_fill = 0.0;        // hull area over the area of its smallest enclosing rectangle
  double polygon_harmonic = 0.0; // the strongest 3rd-8th angular harmonic of the radial residual, over the radius
};

// A disc's hull fills pi/4 of its enclosing rectangle and lies on its circle; a rectangle's
// fills all of it and strays from any circle by ~11% of the radius. A regular n-gon strays
// less (a pentagon 6.6%), but in step with its corners: its radial residual has a strong n-th
// angular harmonic, a disc's ragged outline none. Outlines in between (a triangle, a cut-off
// disc) stay undecided.
FaceOutline face_outline(const PointList& cloud, const DetectedPlane& face, double max_circle_rms,
                         double max_circle_harmonic, double min_rect_fill);

}  // namespace cloudshape::pipeline
