// Per-source comparison of recognizer results: what echo prints against what recognize prints.
#include "same_results.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "report/result_json.hpp"

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

bool close(double a, double b) { return std::abs(a - b) <= 1e-6 * std::max({1.0, std::abs(a), std::abs(b)}); }

template <typename T>
std::string str(const T& v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

class Differences {
 public:
  explicit Differences(std::vector<std::string>& out) : out_(out) {}
  void where(const std::string& w) { where_ = w; }
  template <typename T>
  void equal(const std::string& what, const T& actual, const T& expected) {
    if (!(actual == expected)) add(what, str(actual), str(expected));
  }
  void near(const std::string& what, double actual, double expected) {
    if (!close(actual, expected)) add(what, str(actual), str(expected));
  }

 private:
  void add(const std::string& what, const std::string& actual, const std::string& expected) {
    out_.push_back(where_ + ": " + what + " is " + actual + ", expected " + expected);
  }
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
  d.equal("partial", a.partial, e.partial);
  d.equal("corner key-points", a.keypoints.corner, e.keypoints.corner);
  d.equal("edge key-points", a.keypoints.edge, e.keypoints.edge);
  d.equal("border key-points", a.keypoints.border, e.keypoints.border);
  d.equal("reason", a.reason, e.reason);
}

}  // namespace

std::vector<std::string> result_differences(const std::vector<std::string>& expected_lines,
                                            const std::vector<std::string>& actual_lines) {
  std::vector<std::string> diffs;
  const Results expected = by_source(expected_lines, "expected", diffs);
  const Results actual = by_source(actual_lines, "actual", diffs);
  for (const auto& [source, a] : actual) {
    if (expected.count(source) == 0) diffs.push_back(source + ": unexpected result");
  }
  Differences d(diffs);
  for (const auto& [source, e] : expected) {
    const auto found = actual.find(source);
    if (found == actual.end()) {
      diffs.push_back(source + ": no result");
      continue;
    }
    const pipeline::RecognitionResult& a = found->second;
    d.where(source);
    d.equal("points_in", a.points_in, e.points_in);
    d.equal("points_used", a.points_used, e.points_used);
    d.near("resolution", a.resolution, e.resolution);
    d.equal("object count", a.objects.size(), e.objects.size());
    for (std::size_t i = 0; i < std::min(a.objects.size(), e.objects.size()); ++i) {
      d.where(source + " object " + std::to_string(i));
      compare_object(d, a.objects[i], e.objects[i]);
    }
  }
  return diffs;
}

}  // namespace cloudshape::testing
