// Parsing of the tool's composite arguments ("30,20,10", "X,Y,Z") and of enum-like words.
// Errors name the option so the one-line message points straight at the culprit.
#pragma once

#include "io/cloud_writers.hpp"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace cloudshape::synth_tool {

// Comma-separated finite numbers; throws std::invalid_argument("OPTION: ...").
std::vector<double> parse_numbers(const std::string& text, const std::string& option);

// Exactly three comma-separated numbers.
Eigen::Vector3d parse_point(const std::string& text, const std::string& option);

io::PcdEncoding parse_pcd_encoding(const std::string& text);

}  // namespace cloudshape::synth_tool
