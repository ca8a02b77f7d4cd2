// Which parts of a drawn wireframe lie behind the cloud's points: each projected segment cut
// into pieces, a piece hidden where the points drawn over it are clearly nearer the camera.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "render/point_splat.hpp"
#include "render/view.hpp"
#include "render/wireframe.hpp"

namespace cloudshape::render {

struct WirePiece {
  Eigen::Vector2d from, to;  // pixels
  bool hidden = false;
};

// Pieces of at most a few pixels are judged, then runs of the same verdict joined. A piece is
// hidden where the nearest point within two pixels of it is nearer than the piece by more than the
// larger of 3% of the points' depth range and 5% of the wireframe's size, so that the surface a
// wire lies on does not hide it. Outlines (Polyline::outline) are never hidden.
std::vector<WirePiece> wire_pieces(const View& view, const Wireframe& wireframe, const DepthBuffer& depth);

}  // namespace cloudshape::render
