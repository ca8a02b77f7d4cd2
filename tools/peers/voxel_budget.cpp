#include "voxel_budget.hpp"

#include <pcl/common/common.h>
#include <pcl/filters/voxel_grid.h>

#include <cmath>

namespace peers {

namespace {

Cloud::Ptr voxel_grid(const Cloud::ConstPtr& input, float leaf) {
  auto out = pcl::make_shared<Cloud>();
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud(input);
  grid.setLeafSize(leaf, leaf, leaf);
  grid.filter(*out);
  return out;
}

}  // namespace

Downsampled downsample_to_budget(const Cloud::ConstPtr& input, const VoxelBudget& budget) {
  pcl::PointXYZ lo, hi;
  pcl::getMinMax3D(*input, lo, hi);
  Downsampled d;
  d.diagonal = (hi.getVector3fMap() - lo.getVector3fMap()).norm();
  d.leaf = static_cast<float>(d.diagonal / budget.divisions);
  d.cloud = voxel_grid(input, d.leaf);
  // A surface's voxel count falls with the square of the edge: one or two regrowths suffice.
  for (int i = 0; i < 4 && d.cloud->size() > budget.max_points; ++i) {
    d.leaf *= 1.02f * std::sqrt(static_cast<float>(d.cloud->size()) / budget.max_points);
    d.cloud = voxel_grid(input, d.leaf);
  }
  return d;
}

}  // namespace peers
