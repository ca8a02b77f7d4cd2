// pcl-lccp FILE.pcd...
//
// The scene pipeline of tools/bench_peers.sh: PCL's model-free object segmentation of a
// table-top frame. NaN points dropped, the table plane found by RANSAC (1 cm band, as for a
// Kinect in metres) and removed, then SupervoxelClustering + LCCPSegmentation with the
// parameters of PCL's LCCP example (examples/segmentation/example_lccp_segmentation.cpp, its
// defaults: voxel 0.0075, seed 0.03, colour 0, spatial 1, normal 4, no single-camera
// transform, no refinement; concavity tolerance 10 degrees, smoothness check 0.1, k factor 0,
// no sanity check, no minimum segment size), and the labels carried back to the points.
// It segments only: it names no shape, fits nothing. One JSON line per file; "ms" is the
// pipeline alone, the file read excluded.
#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/filters/extract_indices.h>
#include <pcl/filters/filter.h>
#include <pcl/io/pcd_io.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/lccp_segmentation.h>
#include <pcl/segmentation/sac_segmentation.h>
#include <pcl/segmentation/supervoxel_clustering.h>

#include <cstdint>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include "peer_clock.hpp"

namespace {

using PointT = pcl::PointXYZRGBA;  // the example's point type; mOSD frames carry rgba
using SceneCloud = pcl::PointCloud<PointT>;

// The example's defaults (its command-line options unset).
constexpr float kVoxelResolution = 0.0075f;
constexpr float kSeedResolution = 0.03f;
constexpr float kColorImportance = 0.0f;
constexpr float kSpatialImportance = 1.0f;
constexpr float kNormalImportance = 4.0f;
constexpr float kConcavityTolerance = 10.0f;
constexpr float kSmoothnessThreshold = 0.1f;
constexpr unsigned kKFactor = 0;
constexpr std::uint32_t kMinSegmentSize = 0;
constexpr float kTableBand = 0.01f;  // metres

struct Scene {
  std::size_t points = 0, table = 0, supervoxels = 0, segments = 0;
  double table_ms = 0, supervoxel_ms = 0, lccp_ms = 0, total_ms = 0;
};

SceneCloud::Ptr without_table(const SceneCloud::Ptr& cloud, std::size_t& table) {
  pcl::SACSegmentation<PointT> seg;
  seg.setOptimizeCoefficients(true);
  seg.setModelType(pcl::SACMODEL_PLANE);
  seg.setMethodType(pcl::SAC_RANSAC);
  seg.setDistanceThreshold(kTableBand);
  seg.setMaxIterations(1000);
  seg.setInputCloud(cloud);
  auto inliers = pcl::make_shared<pcl::PointIndices>();
  pcl::ModelCoefficients coefficients;
  seg.segment(*inliers, coefficients);
  table = inliers->indices.size();
  auto rest = pcl::make_shared<SceneCloud>();
  pcl::ExtractIndices<PointT> extract;
  extract.setInputCloud(cloud);
  extract.setIndices(inliers);
  extract.setNegative(true);
  extract.filter(*rest);
  return rest;
}

Scene segment(const SceneCloud::Ptr& frame) {
  Scene s;
  peers::Stopwatch total, step;
  auto finite = pcl::make_shared<SceneCloud>();
  pcl::Indices kept;
  pcl::removeNaNFromPointCloud(*frame, *finite, kept);
  s.points = finite->size();
  const SceneCloud::Ptr objects = without_table(finite, s.table);
  s.table_ms = step.lap_ms();

  pcl::SupervoxelClustering<PointT> super(kVoxelResolution, kSeedResolution);
  super.setUseSingleCameraTransform(false);
  super.setInputCloud(objects);
  super.setColorImportance(kColorImportance);
  super.setSpatialImportance(kSpatialImportance);
  super.setNormalImportance(kNormalImportance);
  std::map<std::uint32_t, pcl::Supervoxel<PointT>::Ptr> clusters;
  super.extract(clusters);
  std::multimap<std::uint32_t, std::uint32_t> adjacency;
  super.getSupervoxelAdjacency(adjacency);
  s.supervoxels = clusters.size();
  s.supervoxel_ms = step.lap_ms();

  pcl::LCCPSegmentation<PointT> lccp;
  lccp.setConcavityToleranceThreshold(kConcavityTolerance);
  lccp.setSanityCheck(false);
  lccp.setSmoothnessCheck(true, kVoxelResolution, kSeedResolution, kSmoothnessThreshold);
  lccp.setKFactor(kKFactor);
  lccp.setInputSupervoxels(clusters, adjacency);
  lccp.setMinSegmentSize(kMinSegmentSize);
  lccp.segment();
  // Per-point segment labels, as the example produces them: the answer a user goes on with.
  pcl::PointCloud<pcl::PointXYZL>::Ptr labelled = super.getLabeledCloud();
  lccp.relabelCloud(*labelled);
  std::map<std::uint32_t, std::set<std::uint32_t>> segments;
  lccp.getSegmentToSupervoxelMap(segments);
  s.segments = segments.size();
  s.lccp_ms = step.lap_ms();
  s.total_ms = total.lap_ms();
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: pcl-lccp FILE.pcd...\n");
    return 2;
  }
  for (int i = 1; i < argc; ++i) {
    const std::string path = argv[i];
    auto frame = pcl::make_shared<SceneCloud>();
    if (pcl::io::loadPCDFile(path, *frame) != 0) {
      std::fprintf(stderr, "pcl-lccp: cannot read %s\n", path.c_str());
      return 2;
    }
    const Scene s = segment(frame);
    const std::string base = path.substr(path.find_last_of('/') + 1);
    std::printf(
        "{\"tool\":\"pcl_lccp\",\"version\":\"%s\",\"file\":\"%s\",\"points\":%zu,\"table\":%zu,"
        "\"supervoxels\":%zu,\"segments\":%zu,\"ms\":%.3f,"
        "\"stages_ms\":{\"table\":%.3f,\"supervoxels\":%.3f,\"lccp\":%.3f}}\n",
        PCL_VERSION_PRETTY, base.c_str(), s.points, s.table, s.supervoxels, s.segments, s.total_ms,
        s.table_ms, s.supervoxel_ms, s.lccp_ms);
    std::fflush(stdout);
  }
  return 0;
}
