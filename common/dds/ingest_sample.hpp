// What cloudshape-ingest does with one received raw cloud, without DDS: check the sample (x y z
// triples, limits, layout, finite points), then object_clouds with its grid as recognize_cloud does.
#pragma once

#include <string>
#include <vector>

#include "cloudshape.h"
#include "config/pipeline_config.hpp"
#include "dds/raw_cloud_error.hpp"
#include "geometry/point_cloud.hpp"
#include "parallel/thread_pool.hpp"

namespace cloudshape::dds {

struct RawCloudPoints {
  PointList points;  // the finite points, in sample order
  GridLayout grid;   // organized samples: the pixel of each of `points`; empty otherwise
  std::size_t non_finite_dropped = 0;
};

// Throws RawCloudError when xyz is not whole x y z triples, holds no point, more points than
// limits.max_points or more coordinate bytes than limits.max_bytes, a bad layout
// (raw_cloud_layout), no finite point, or a point beyond limits.max_coordinate.
RawCloudPoints raw_cloud_points(const msg::RawCloud& cloud, const config::InputConfig& limits);

// Throws RawCloudError when `cloud` (of `count` points sent, NaN ones included) kept no finite
// point or holds a point beyond limits.max_coordinate.
void check_usable_points(const RawCloudPoints& cloud, std::size_t count, const config::InputConfig& limits);

// One filtered cloud per object of `cloud`, each with `header` and object_index/object_count set
// (one with object_count 0 when preprocessing finds no object), as recognize_cloud splits it.
// A `pool` runs the segmentation's searches and the objects' preprocessing: the same clouds.
std::vector<msg::FilteredCloud> filtered_clouds(const msg::CloudHeader& header, const RawCloudPoints& cloud,
                                                const config::PipelineConfig& cfg, parallel::ThreadPool* pool = nullptr);

// raw_cloud_points, then filtered_clouds. Throws RawCloudError as raw_cloud_points does.
std::vector<msg::FilteredCloud> ingest_raw_cloud(const msg::RawCloud& in, const config::PipelineConfig& cfg,
                                                 parallel::ThreadPool* pool = nullptr);

// The one message a refused cloud becomes: `header` marked failed by `stage` with `text`, as the
// cloud's single object (a raw cloud's own object fields mean nothing).
msg::FilteredCloud refused_cloud(const msg::CloudHeader& header, const std::string& stage, const std::string& text);
msg::FilteredCloud refused_raw_cloud(const msg::RawCloud& in, const std::string& stage, const std::string& text);

}  // namespace cloudshape::dds
