// Per-source comparison of recognizer results: what echo prints against what recognize prints,
// every field of every object (timings excepted: they are measurements, not results).
#include "same_results.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "report/result_json.hpp"
#include "same_axes.hpp"

namespace cloudshape::testing {
namespace {

using Results = std::map<std::string, pipeline::RecognitionResult>;

Results by_source(const std::vector<std::string>& lines, const std::string& side, std::vector<std::string>& diffs) {
  Results results;
  for (const std::string& line : lines) {
    if (line.empty()) continue;
    try {
      pipeline::RecognitionResult r = report::result_from_json_line(line);
      if (results.count(r.source) != 0) diffs.push_back(side + ": two results for " + r.source);
      results[r.source] = r;
    } catch (const std::exception& e) {
      diffs.push_back(side + ": not a result line (" + e.what() + "): " + line);
    }
  }
  return results;
}

bool close(double a, double b) {
  return std::abs(a - b) <= kSameTolerance * std::max({1.0, std::abs(a), std::abs(b)});
}

template <typename T>
std::string str(const T& v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

class Differences {
 public:
  Differences(std::vector<std::string>& out, std::string where) : out_(out), where_(std::move(where)) {}
  template <typename T>
  void equal(const std::string& what, const T& actual, const T& expected) {
    if (!(actual == expected)) add(what + " is " + str(actual) + ", expected " + str(expected));
  }
  void near(const std::string& what, double actual, double expected) {
    if (!close(actual, expected)) add(what + " is " + str(actual) + ", expected " + str(expected));
  }
  void add(const std::string& what) { out_.push_back(where_ + ": " + what); }

 private:
  std::vector<std::string>& out_;
  std::string where_;
};

void compare_object(Differences& d, const pipeline::ObjectResult& a, const pipeline::ObjectResult& e) {
  d.equal("shape", a.shape, e.shape);
  d.near("confidence", a.confidence, e.confidence);
  d.equal("dimension count", a.dimensions.size(), e.dimensions.size());
  for (std::size_t i = 0; i < std::min(a.dimensions.size(), e.dimensions.size()); ++i) {
    d.equal("dimension name", a.dimensions[i].first, e.dimensions[i].first);
    d.near(e.dimensions[i].first, a.dimensions[i].second, e.dimensions[i].second);
  }
  for (int k = 0; k < 3; ++k) d.near("center[" + std::to_string(k) + "]", a.center[k], e.center[k]);
  if (const std::string why = axes_difference(a, e, kSameTolerance); !why.empty()) d.add(why);
  d.equal("partial", a.partial, e.partial);
  d.equal("corner key-points", a.keypoints.corner, e.keypoints.corner);
  d.equal("edge key-points", a.keypoints.edge, e.keypoints.edge);
  d.equal("border key-points", a.keypoints.border, e.keypoints.border);
  d.equal("reason", a.reason, e.reason);
  for (int k = 0; k < 3; ++k) {
    d.near("extent.center[" + std::to_string(k) + "]", a.extent.center[k], e.extent.center[k]);
    d.near("extent.size[" + std::to_string(k) + "]", a.extent.size[k], e.extent.size[k]);
    for (int c = 0; c < 3; ++c)
      d.near("extent.axes[" + std::to_string(k) + "][" + std::to_string(c) + "]", a.extent.axes(k, c),
             e.extent.axes(k, c));
  }
  d.equal("polygon size", a.polygon.size(), e.polygon.size());
  for (std::size_t i = 0; i < std::min(a.polygon.size(), e.polygon.size()); ++i)
    for (int k = 0; k < 2; ++k)
      d.near("polygon[" + std::to_string(i) + "][" + std::to_string(k) + "]", a.polygon[i][k], e.polygon[i][k]);
  d.equal("vertex count", a.vertices.size(), e.vertices.size());
  for (std::size_t i = 0; i < std::min(a.vertices.size(), e.vertices.size()); ++i)
    for (int k = 0; k < 3; ++k)
      d.near("vertices[" + std::to_string(i) + "][" + std::to_string(k) + "]", a.vertices[i][k], e.vertices[i][k]);
  d.equal("regular", a.regular, e.regular);
}

}  // namespace

std::vector<std::string> result_differences(const pipeline::RecognitionResult& expected,
                                            const pipeline::RecognitionResult& actual, const std::string& where) {
  std::vector<std::string> diffs;
  Differences d(diffs, where);
  d.equal("source", actual.source, expected.source);
  d.equal("points_in", actual.points_in, expected.points_in);
  d.equal("points_used", actual.points_used, expected.points_used);
  d.near("resolution", actual.resolution, expected.resolution);
  d.equal("object count", actual.objects.size(), expected.objects.size());
  for (std::size_t i = 0; i < std::min(actual.objects.size(), expected.objects.size()); ++i) {
    Differences od(diffs, where + " object " + std::to_string(i));
    compare_object(od, actual.objects[i], expected.objects[i]);
  }
  return diffs;
}

std::vector<std::string> result_differences(const std::vector<std::string>& expected_lines,
                                            const std::vector<std::string>& actual_lines) {
  std::vector<std::string> diffs;
  const Results expected = by_source(expected_lines, "expected", diffs);
  const Results actual = by_source(actual_lines, "actual", diffs);
  for (const auto& [source, a] : actual) {
    if (expected.count(source) == 0) diffs.push_back(source + ": unexpected result");
  }
  for (const auto& [source, e] : expected) {
    const auto found = actual.find(source);
    if (found == actual.end()) {
      diffs.push_back(source + ": no result");
      continue;
    }
    for (std::string& d : result_differences(e, found->second, source)) diffs.push_back(std::move(d));
  }
  return diffs;
}

}  // namespace cloudshape::testing
