// The plane step of the PCL shape pipeline, as a PCL user writes it: SACSegmentation (RANSAC)
// finds the largest plane, ExtractIndices removes it, repeated while planes are large and the
// shape can have more. open3d_shapes.py peels with the same rule, so both peers do the same
// plane work.
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>

namespace peers {

struct PlanePeelRule {
  float threshold = 0.0f;   // inlier band (the caller's: the voxel edge)
  int max_planes = 6;       // the caller's: the faces or caps the shape has (a box six)
  // A plane holds at least this share of the input: a box's smallest face holds 9%, while a
  // band of a sphere or of a cylinder's side that is one voxel edge thick holds 4-5% and 8%
  // (the caps come first and max_planes stops there).
  double min_share = 0.06;
  int max_iterations = 1000;
};

struct PlanePeelResult {
  int planes = 0;
  std::size_t largest = 0;  // inliers of the largest plane found
};

// Removes the planes from cloud and normals (both shrink in step).
PlanePeelResult peel_planes(pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
                            pcl::PointCloud<pcl::Normal>::Ptr& normals, const PlanePeelRule& rule);

}  // namespace peers
