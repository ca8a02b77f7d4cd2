#include "arguments.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace cloudshape::synth_tool {

std::vector<double> parse_numbers(const std::string& text, const std::string& option) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || item.find_first_not_of(" \t", used) != std::string::npos ||
        !std::isfinite(value))
      throw std::invalid_argument(option + ": '" + item + "' is not a number (in '" + text + "')");
    values.push_back(value);
  }
  if (values.empty()) throw std::invalid_argument(option + ": expected comma-separated numbers");
  return values;
}

Eigen::Vector3d parse_point(const std::string& text, const std::string& option) {
  const auto values = parse_numbers(text, option);
  if (values.size() != 3)
    throw std::invalid_argument(option + ": expected X,Y,Z, got '" + text + "'");
  return {values[0], values[1], values[2]};
}

io::PcdEncoding parse_pcd_encoding(const std::string& text) {
  if (text == "ascii") return io::PcdEncoding::ascii;
  if (text == "binary") return io::PcdEncoding::binary;
  if (text == "binary_compressed") return io::PcdEncoding::binary_compressed;
  throw std::invalid_argument("--pcd-encoding: '" + text +
                              "' is not one of ascii, binary, binary_compressed");
}

}  // namespace cloudshape::synth_tool
