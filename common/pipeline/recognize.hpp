// The whole recognition chain in one call: preprocess -> planes -> keypoints ->
// classify -> solve, the same stage functions the DDS services call one by one.
#pragma once

#include <string>

#include "config/pipeline_config.hpp"
#include "geometry/point_cloud.hpp"
#include "pipeline/result.hpp"

namespace cloudshape::pipeline {

// Recognises every object in `points`. Never throws on geometric content: a cloud
// with no solid in it yields an `unknown` object with a reason.
RecognitionResult recognize_cloud(const PointList& points, const config::PipelineConfig& cfg,
                                  const std::string& source = {});

// The same for an organized cloud: `grid` says where each point sat in the sensor's image
// (GridLayout::organized()), which segmentation uses for pixel neighbours and depth edges.
RecognitionResult recognize_cloud(const PointList& points, const GridLayout& grid,
                                  const config::PipelineConfig& cfg, const std::string& source = {});

}  // namespace cloudshape::pipeline
