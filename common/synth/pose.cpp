#include "synth/pose.hpp"

#include <Eigen/Geometry>

namespace cloudshape::synth {

Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  // A normalised 4D Gaussian is uniform on S^3, hence a uniform (Haar) rotation.
  std::normal_distribution<double> gauss(0.0, 1.0);
  Eigen::Quaterniond q;
  do {
    q = Eigen::Quaterniond(gauss(rng), gauss(rng), gauss(rng), gauss(rng));
  } while (q.norm() < 1e-6);
  q.normalize();
  return q.toRotationMatrix();
}

Pose random_pose(std::mt19937_64& rng, double max_offset) {
  Pose pose;
  // Rows are the local axes in world coordinates; R's columns are, so transpose.
  pose.axes = random_rotation(rng).transpose();
  std::uniform_real_distribution<double> offset(-max_offset, max_offset);
  if (max_offset > 0.0) pose.center = {offset(rng), offset(rng), offset(rng)};
  return pose;
}

}  // namespace cloudshape::synth
