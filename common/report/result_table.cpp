#include "report/result_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace cloudshape::report {
namespace {

constexpr int kShapeWidth = 16;       // "pentagonal_prism"
constexpr int kDimensionsWidth = 44;  // three dimensions of 4 significant digits below 1

// Four significant digits in plain notation for the lengths a sensor gives (a golf ball in
// metres, a crate in millimetres); exponent notation only outside 1e-3..1e6.
std::string length_text(double v) {
  char buf[64];
  const double a = std::fabs(v);
  if (a >= 1e-3 && a < 1e6) {
    const int magnitude = static_cast<int>(std::floor(std::log10(a)));
    int decimals = std::max(0, 3 - magnitude);
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    // 9.99996 rounds up to "10.000": one digit too many once it reaches the next power of ten.
    if (decimals > 0 && std::fabs(std::atof(buf)) >= std::pow(10.0, magnitude + 1)) {
      std::snprintf(buf, sizeof buf, "%.*f", --decimals, v);
    }
  } else {
    std::snprintf(buf, sizeof buf, "%.4g", v);
  }
  return buf;
}

std::string row(const TableLayout& layout, const std::string& file, const std::string& shape,
                const std::string& dimensions, const std::string& confidence,
                const std::string& partial, const std::string& ms, const std::string& note) {
  char buf[1024];
  std::snprintf(buf, sizeof buf, "%-*s  %-*s  %-*s  %10s  %7s  %8s",
                static_cast<int>(layout.file_width), file.c_str(), kShapeWidth, shape.c_str(),
                kDimensionsWidth, dimensions.c_str(), confidence.c_str(), partial.c_str(),
                ms.c_str());
  std::string line = buf;
  if (!note.empty()) line += "  " + note;
  // Padding of the last columns is not needed when nothing follows them.
  line.erase(line.find_last_not_of(' ') + 1);
  return line;
}

}  // namespace

TableLayout table_layout(const std::vector<std::string>& sources) {
  TableLayout layout;
  for (const auto& s : sources) layout.file_width = std::max(layout.file_width, s.size());
  return layout;
}

std::string table_header(const TableLayout& layout) {
  return row(layout, "file", "shape", "dimensions", "confidence", "partial", "ms", "");
}

std::string dimensions_text(const pipeline::ObjectResult& object) {
  std::string text;
  for (const auto& [name, value] : object.dimensions) {
    if (!text.empty()) text += ' ';
    text += name + ' ' + length_text(value);
  }
  return text.empty() ? "-" : text;
}

std::vector<std::string> table_rows(const pipeline::RecognitionResult& result,
                                    const TableLayout& layout) {
  char ms[32];
  std::snprintf(ms, sizeof ms, "%.1f", result.timings.total_ms);
  std::vector<std::string> rows;
  if (result.objects.empty()) {
    rows.push_back(row(layout, result.source, "-", "no object found", "-", "-", ms, ""));
    return rows;
  }
  for (const auto& o : result.objects) {
    char confidence[32];
    std::snprintf(confidence, sizeof confidence, "%.2f", o.confidence);
    rows.push_back(row(layout, result.source, o.shape, dimensions_text(o), confidence,
                       o.partial ? "yes" : "no", ms, o.reason));
  }
  return rows;
}

}  // namespace cloudshape::report
