// Conversions between the IDL types (cloudshape.idl) and the pipeline's core types.
// Exact both ways: every value travels as float64, so core -> IDL -> core is the identity.
#pragma once

#include <optional>
#include <string>

#include "cloudshape.h"
#include "geometry/point_cloud.hpp"
#include "pipeline/classify.hpp"
#include "pipeline/keypoints.hpp"
#include "pipeline/planes.hpp"
#include "pipeline/preprocess.hpp"
#include "pipeline/result.hpp"

namespace cloudshape::dds {

// Points <-> flat x0 y0 z0 x1 ... (throws std::invalid_argument when not a multiple of 3).
std::vector<double> to_xyz(const PointList& points);
PointList from_xyz(const std::vector<double>& xyz);

// A file's cloud as cloudshape-inject publishes it: xyz and, when grid.organized(), width,
// height and pixel (0, 0 and empty otherwise). The header is the caller's.
msg::RawCloud to_raw_cloud(const PointList& points, const GridLayout& grid);

// Preprocessing output plus the raw cloud's point count.
msg::CloudData to_msg(const pipeline::PreprocessedCloud& cloud, std::size_t points_in);
// One object (a part of cloud.points) of a preprocessed cloud.
msg::CloudData to_msg(const PointList& object, const pipeline::PreprocessedCloud& cloud,
                      std::size_t points_in);
pipeline::PreprocessedCloud from_msg(const msg::CloudData& cloud);
// The sensor's position, carried with every object so the solver sees what recognize_cloud sees
// (a container seen into needs it).
void set_viewpoint(msg::CloudData& cloud, const std::optional<Point>& viewpoint);
std::optional<Point> viewpoint_of(const msg::CloudData& cloud);

msg::PlaneSegmentation to_msg(const pipeline::PlaneSegmentation& planes);
pipeline::PlaneSegmentation from_msg(const msg::PlaneSegmentation& planes);

msg::KeypointSet to_msg(const pipeline::KeypointSet& keypoints);
pipeline::KeypointSet from_msg(const msg::KeypointSet& keypoints);

msg::ClassificationData to_msg(const pipeline::Classification& classification);
pipeline::Classification from_msg(const msg::ClassificationData& classification);

msg::ObjectResult to_msg(const pipeline::ObjectResult& object);
pipeline::ObjectResult from_msg(const msg::ObjectResult& object);

msg::StageTimings to_msg(const pipeline::StageTimings& timings);
// total_ms is the sum of the stages, as recognize_cloud computes it.
pipeline::StageTimings from_msg(const msg::StageTimings& timings);

// The JSON-level result (what cloudshape-recognize prints) rebuilt from a result message.
pipeline::RecognitionResult to_recognition_result(const msg::ShapeResult& result);
// ... from the result messages of every object of one cloud, in object order: objects
// concatenated, preprocessing timed once, the other stages summed as recognize_cloud does.
pipeline::RecognitionResult to_recognition_result(const std::vector<msg::ShapeResult>& objects);

// The shape named `name` (INTERFACE.md), unknown for names this build does not know.
pipeline::Shape shape_from_name(const std::string& name);

}  // namespace cloudshape::dds
