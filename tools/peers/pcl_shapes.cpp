// pcl-shapes --shape box|cylinder|cone|sphere FILE.pcd
//
// The PCL pipeline of tools/bench_peers.sh for one solid, told which shape to fit (a peer is
// given the answer; cloudshape has to find it): voxel grid at cloudshape's point budget,
// normals (NormalEstimationOMP, 16 neighbours, all cores), RANSAC planes peeled while large
// (at most the shape's faces or caps: box 6, cylinder 2, cone 1; a sphere gets one search that
// finds none), then the SAC fit of the shape on what is left (SACSegmentationFromNormals:
// cylinder, cone, sphere; a box is its planes). Settings follow PCL's cylinder segmentation
// tutorial (normal distance weight 0.1, up to 10 000 iterations); the inlier band is the voxel
// edge (the clouds' noise is well inside it).
// Prints one JSON line; "ms" is the pipeline alone, the file read excluded.
#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/io/pcd_io.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "peer_clock.hpp"
#include "plane_peel.hpp"
#include "voxel_budget.hpp"

namespace {

struct Fit {
  std::size_t inliers = 0;
  int coefficients = 0;
};

// The planes a shape can show: faces, caps; a sphere's one search finds none.
int max_planes_for(const std::string& shape) {
  if (shape == "box") return 6;
  if (shape == "cylinder") return 2;
  return 1;
}

// The SAC model for a curved shape, or -1 for a box (its planes are the whole answer).
int model_for(const std::string& shape) {
  if (shape == "cylinder") return pcl::SACMODEL_CYLINDER;
  if (shape == "cone") return pcl::SACMODEL_CONE;
  if (shape == "sphere") return pcl::SACMODEL_NORMAL_SPHERE;
  return -1;
}

Fit fit_model(int model, const peers::Cloud::Ptr& cloud,
              const pcl::PointCloud<pcl::Normal>::Ptr& normals, float threshold, float diagonal) {
  Fit fit;
  if (model < 0 || cloud->size() < 10) return fit;
  pcl::SACSegmentationFromNormals<pcl::PointXYZ, pcl::Normal> seg;
  seg.setOptimizeCoefficients(true);
  seg.setModelType(model);
  seg.setMethodType(pcl::SAC_RANSAC);
  seg.setNormalDistanceWeight(0.1);
  seg.setMaxIterations(10000);
  seg.setDistanceThreshold(threshold);
  seg.setRadiusLimits(0.0, diagonal);
  seg.setInputCloud(cloud);
  seg.setInputNormals(normals);
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coefficients;
  seg.segment(inliers, coefficients);
  fit.inliers = inliers.indices.size();
  fit.coefficients = static_cast<int>(coefficients.values.size());
  return fit;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 || std::strcmp(argv[1], "--shape") != 0 ||
      (model_for(argv[2]) < 0 && std::string(argv[2]) != "box")) {
    std::fprintf(stderr, "usage: pcl-shapes --shape box|cylinder|cone|sphere FILE.pcd\n");
    return 2;
  }
  const std::string shape = argv[2];
  const std::string path = argv[3];
  auto input = pcl::make_shared<peers::Cloud>();
  if (pcl::io::loadPCDFile(path, *input) != 0) {
    std::fprintf(stderr, "pcl-shapes: cannot read %s\n", path.c_str());
    return 2;
  }

  peers::Stopwatch total, step;
  const peers::Downsampled down = peers::downsample_to_budget(input);
  const double voxel_ms = step.lap_ms();

  auto normals = pcl::make_shared<pcl::PointCloud<pcl::Normal>>();
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimate;
  estimate.setSearchMethod(pcl::make_shared<pcl::search::KdTree<pcl::PointXYZ>>());
  estimate.setInputCloud(down.cloud);
  estimate.setKSearch(16);
  estimate.compute(*normals);
  const double normals_ms = step.lap_ms();

  peers::PlanePeelRule rule;
  rule.threshold = down.leaf;
  rule.max_planes = max_planes_for(shape);
  peers::Cloud::Ptr rest = down.cloud;
  const peers::PlanePeelResult planes = peers::peel_planes(rest, normals, rule);
  const double planes_ms = step.lap_ms();

  const Fit fit = fit_model(model_for(shape), rest, normals, rule.threshold, down.diagonal);
  const double fit_ms = step.lap_ms();
  const double total_ms = total.lap_ms();

  const std::string base = path.substr(path.find_last_of('/') + 1);
  std::printf(
      "{\"tool\":\"pcl\",\"version\":\"%s\",\"file\":\"%s\",\"shape\":\"%s\",\"points_in\":%zu,"
      "\"points_used\":%zu,\"leaf\":%.6g,\"planes\":%d,\"fit_inliers\":%zu,\"fit_found\":%s,"
      "\"ms\":%.3f,\"stages_ms\":{\"voxel\":%.3f,\"normals\":%.3f,\"planes\":%.3f,\"fit\":%.3f}}\n",
      PCL_VERSION_PRETTY, base.c_str(), shape.c_str(), input->size(), down.cloud->size(),
      down.leaf, planes.planes, fit.inliers, fit.coefficients > 0 ? "true" : "false", total_ms,
      voxel_ms, normals_ms, planes_ms, fit_ms);
  return 0;
}
