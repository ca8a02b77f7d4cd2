// Where a 3-D point lands in a picture panel: a camera (pinhole or orthographic) and the scale
// and offset that fit what it sees into the panel's pixels, x to the right and y down.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <utility>
#include <vector>

namespace cloudshape::render {

struct Camera {
  // Rows: the camera's right, down and forward directions in world coordinates.
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d eye = Eigen::Vector3d::Zero();
  bool perspective = true;

  Eigen::Vector3d to_camera(const Eigen::Vector3d& p) const { return rotation * (p - eye); }
  // Unit vector from `p` towards the camera (for an orthographic camera: against forward).
  Eigen::Vector3d toward_viewer(const Eigen::Vector3d& p) const;
};

struct PixelRect {
  double x = 0, y = 0, width = 0, height = 0;
  bool contains(const Eigen::Vector2d& p) const {
    return p.x() >= x && p.y() >= y && p.x() < x + width && p.y() < y + height;
  }
};

struct View {
  Camera camera;
  double scale = 1.0;                               // pixels per image-plane unit
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();  // pixel of the image-plane origin

  // Image-plane coordinates (x/z, y/z for a pinhole); none behind a pinhole camera.
  std::optional<Eigen::Vector2d> image_plane(const Eigen::Vector3d& p) const;
  // The pixel (x, y) and the depth along forward; none behind a pinhole camera.
  std::optional<Eigen::Vector3d> pixel(const Eigen::Vector3d& p) const;
  // The segment's pixels, cut where it passes behind a pinhole camera; none if wholly behind.
  std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> segment(const Eigen::Vector3d& a,
                                                                     const Eigen::Vector3d& b) const;
};

// A view of `camera` scaled and centred so that the bulk of `points` (their 1st to 99th
// percentile, so that a few strays do not shrink the rest), widened `zoom_out` times about its
// middle, plus `also` fill `rect` less `margin` pixels on every side. `also` (wireframe corners)
// may widen the frame to at most twice the points'.
View fit_view(const Camera& camera, const std::vector<Eigen::Vector3d>& points,
              const std::vector<Eigen::Vector3d>& also, const PixelRect& rect, double margin,
              double zoom_out = 1.0);

}  // namespace cloudshape::render
