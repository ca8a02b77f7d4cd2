// One function per solid shape, each turning a result's dimensions and pose into the polylines
// of its wireframe; solid_wireframe() picks one by shape name. A new shape is one more function.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "pipeline/result.hpp"
#include "render/wireframe.hpp"

namespace cloudshape::render {

// A right prism: `polygon` (counter-clockwise [u, v] pairs in the plane of axes rows 1 and 2)
// extruded by `height` along axes row 0, centred on `center`.
Wireframe extrusion(const Eigen::Vector3d& center, const Eigen::Matrix3d& axes,
                    const std::vector<Eigen::Vector2d>& polygon, double height);

// A truncated right circular cone (cylinder: equal radii; cone: top_radius 0) whose base
// circle is centred on `base` with the axis `axis` pointing from base to top.
Wireframe round_solid(const Eigen::Vector3d& base, const Eigen::Matrix3d& axes, double radius,
                      double top_radius, double height, const Eigen::Vector3d& toward_viewer);

Wireframe box_wireframe(const pipeline::ObjectResult& o, const Eigen::Vector3d& toward_viewer);
Wireframe pentagonal_prism_wireframe(const pipeline::ObjectResult& o, const Eigen::Vector3d& toward_viewer);
Wireframe tetrahedron_wireframe(const pipeline::ObjectResult& o, const Eigen::Vector3d& toward_viewer);
Wireframe cylinder_wireframe(const pipeline::ObjectResult& o, const Eigen::Vector3d& toward_viewer);
Wireframe cone_wireframe(const pipeline::ObjectResult& o, const Eigen::Vector3d& toward_viewer);
Wireframe sphere_wireframe(const pipeline::ObjectResult& o, const Eigen::Vector3d& toward_viewer);

}  // namespace cloudshape::render
