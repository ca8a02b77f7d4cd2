// Moments of point sets and what the neighbour graphs derive from them (a normal, a line's
// direction, a node's spacing): shared by the organized and the voxel graph builders.
#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "parallel/thread_pool.hpp"
#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment::detail {

// Nodes per block of the parallel normal loops: a few thousand blocks' overhead at most.
constexpr std::size_t kNodesPerBlock = 512;

// Running first and second moments of a point set, for a normal without storing the points.
// The second moments are symmetric: six sums, each the same products in the same order as the
// full outer product's entry (the same covariance to the bit, two thirds of the work).
struct Moments {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // subtracted first: keeps float64 sums exact enough far from 0
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double xx = 0.0, xy = 0.0, xz = 0.0, yy = 0.0, yz = 0.0, zz = 0.0;
  std::size_t count = 0;

  void add(const Point& p) {
    const Eigen::Vector3d d = p - origin;
    sum += d;
    xx += d.x() * d.x();
    xy += d.y() * d.x();
    xz += d.z() * d.x();
    yy += d.y() * d.y();
    yz += d.z() * d.y();
    zz += d.z() * d.z();
    ++count;
  }
  // At least one point added.
  Eigen::Matrix3d covariance() const {
    Eigen::Matrix3d outer;
    outer << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    const Eigen::Vector3d mean = sum / static_cast<double>(count);
    return outer / static_cast<double>(count) - mean * mean.transpose();
  }
};

// Normal (smallest principal direction) and surface variation; a default up normal when the
// neighbourhood is too small to say. `spread`, if given: second over first standard deviation.
void normal_of(const Moments& m, Eigen::Vector3d& normal, double& curvature, double* spread = nullptr);

// Whether a neighbourhood of three points or more spreads less than `line` across its length
// (normal_of's spread, from the eigenvalues alone: the direct solver computes them the same way
// with or without eigenvectors), and then its direction (the largest principal one, unit).
bool along_a_line(const Moments& m, double line, Eigen::Vector3d& direction);

// Each node's mean distance to its graph neighbours (`fallback` for a node without any).
void fill_spacing(NeighbourGraph& g, double fallback, parallel::ThreadPool* pool);

}  // namespace cloudshape::segment::detail
