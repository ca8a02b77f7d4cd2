// The voxel grid of the PCL pipelines at cloudshape's point budget, so that every tool in the
// comparison works on a cloud of about the same size: the edge starts at the bounding-box
// diagonal / 200 and grows until at most 12 000 points remain (config/pipeline.yaml,
// preprocess.voxel_divisions and max_points). open3d_shapes.py applies the same rule.
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>

namespace peers {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

struct VoxelBudget {
  double divisions = 200.0;
  std::size_t max_points = 12000;
};

struct Downsampled {
  Cloud::Ptr cloud;
  float leaf = 0.0f;      // the voxel edge used
  float diagonal = 0.0f;  // of the input's bounding box
};

Downsampled downsample_to_budget(const Cloud::ConstPtr& input, const VoxelBudget& budget = {});

}  // namespace peers
