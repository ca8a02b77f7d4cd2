#include "plane_peel.hpp"

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/filters/extract_indices.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <algorithm>

namespace peers {

namespace {

template <typename PointT>
void drop(typename pcl::PointCloud<PointT>::Ptr& cloud, const pcl::PointIndices::Ptr& indices) {
  auto rest = pcl::make_shared<pcl::PointCloud<PointT>>();
  pcl::ExtractIndices<PointT> extract;
  extract.setInputCloud(cloud);
  extract.setIndices(indices);
  extract.setNegative(true);
  extract.filter(*rest);
  cloud = rest;
}

}  // namespace

PlanePeelResult peel_planes(pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
                            pcl::PointCloud<pcl::Normal>::Ptr& normals, const PlanePeelRule& rule) {
  const auto floor = static_cast<std::size_t>(rule.min_share * static_cast<double>(cloud->size()));
  pcl::SACSegmentation<pcl::PointXYZ> seg;
  seg.setOptimizeCoefficients(true);
  seg.setModelType(pcl::SACMODEL_PLANE);
  seg.setMethodType(pcl::SAC_RANSAC);
  seg.setDistanceThreshold(rule.threshold);
  seg.setMaxIterations(rule.max_iterations);
  PlanePeelResult result;
  while (result.planes < rule.max_planes && cloud->size() >= floor && cloud->size() >= 3) {
    auto inliers = pcl::make_shared<pcl::PointIndices>();
    pcl::ModelCoefficients coefficients;
    seg.setInputCloud(cloud);
    seg.segment(*inliers, coefficients);
    if (inliers->indices.size() < floor || inliers->indices.empty()) break;
    result.largest = std::max(result.largest, inliers->indices.size());
    ++result.planes;
    drop<pcl::PointXYZ>(cloud, inliers);
    drop<pcl::Normal>(normals, inliers);
  }
  return result;
}

}  // namespace peers
