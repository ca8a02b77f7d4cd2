// The whole recognition chain in one call: preprocess -> planes -> keypoints ->
// classify -> solve, the same stage functions the DDS services call one by one.
#pragma once

#include <string>

#include "config/pipeline_config.hpp"
#include "geometry/point_cloud.hpp"
#include "parallel/thread_pool.hpp"
#include "pipeline/result.hpp"

namespace cloudshape::pipeline {

// Recognises every object in `points`. Never throws on geometric content: a cloud
// with no solid in it yields an `unknown` object with a reason. With a `pool` the objects of a
// scene and the neighbour searches run on its threads; the answer is the same for any pool (or
// none): only the timings differ.
RecognitionResult recognize_cloud(const PointList& points, const config::PipelineConfig& cfg,
                                  const std::string& source = {}, parallel::ThreadPool* pool = nullptr);

// The same for an organized cloud: `grid` says where each point sat in the sensor's image
// (GridLayout::organized()), which segmentation uses for pixel neighbours and depth edges.
RecognitionResult recognize_cloud(const PointList& points, const GridLayout& grid,
                                  const config::PipelineConfig& cfg, const std::string& source = {},
                                  parallel::ThreadPool* pool = nullptr);

}  // namespace cloudshape::pipeline
