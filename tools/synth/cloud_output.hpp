// Writing a generated cloud in the format its file name asks for, plus its ground-truth JSON.
// Formats: .pcd (encoding selectable), .ply (binary little-endian), .xyz / .txt.
#pragma once

#include "geometry/point_cloud.hpp"
#include "io/cloud_writers.hpp"

#include <nlohmann/json.hpp>
#include <string>

namespace cloudshape::synth_tool {

// Throws std::invalid_argument("PATH: unsupported output extension ...") so a bad -o fails
// before any sampling work is done.
void check_output_path(const std::string& path);

void write_cloud(const std::string& path, const PointList& points, io::PcdEncoding pcd_encoding);

// PATH with its extension replaced by .json ("out/box_000.pcd" -> "out/box_000.json").
std::string ground_truth_path(const std::string& cloud_path);

// One line, like the recognizer's JSON Lines output, so the two are easy to diff.
void write_json(const std::string& path, const nlohmann::json& document);

}  // namespace cloudshape::synth_tool
