// Result-to-truth matching and error bookkeeping for the accuracy benchmark.
// Matching is greedy by centre distance, so each result answers at most one truth.
#include "accuracy_score.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "geometry/polygon.hpp"

namespace cloudshape::bench {

namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b, bool signed_direction) {
  const double c = a.normalized().dot(b.normalized());
  return std::acos(std::clamp(signed_direction ? c : std::abs(c), -1.0, 1.0)) * kRadToDeg;
}

}  // namespace

std::vector<int> match_results(const TestCloud& cloud, const pipeline::RecognitionResult& r) {
  // An `unknown` result carries no pose (its centre is left at the origin), so results with a
  // shape are matched first and unknown ones only answer truths still left over.
  std::vector<std::tuple<bool, double, int, int>> pairs;  // unknown, distance, truth, result
  for (int t = 0; t < static_cast<int>(cloud.truths.size()); ++t) {
    const Truth& truth = cloud.truths[t];
    for (int o = 0; o < static_cast<int>(r.objects.size()); ++o) {
      const double d = (r.objects[o].center - truth.center).norm();
      if (!cloud.gate_matching || d <= 0.5 * truth.size)
        pairs.emplace_back(r.objects[o].shape == "unknown", d, t, o);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<int> result_of(cloud.truths.size(), -1);
  std::vector<bool> used(r.objects.size(), false);
  for (const auto& [unknown, d, t, o] : pairs) {
    if (result_of[t] >= 0 || used[o]) continue;
    result_of[t] = o;
    used[o] = true;
  }
  return result_of;
}

bool same_shape(const Truth& truth, const pipeline::ObjectResult& result) {
  if (result.shape != truth.shape) return false;
  if (truth.polygon.empty()) return true;
  return result.polygon.size() == truth.polygon.size();
}

std::vector<double> dimension_errors(const Truth& truth, const pipeline::ObjectResult& result) {
  std::vector<double> errors;
  if (!truth.polygon.empty()) {
    const auto rel = [](double got, double want) { return std::abs(got - want) / want; };
    for (const auto& [name, got] : result.dimensions)
      for (const auto& [want_name, want] : truth.dimensions)
        if (name == "height" && want_name == "height") errors.push_back(rel(got, want));
    if (result.polygon.size() >= 3) {
      errors.push_back(rel(std::sqrt(std::abs(geometry::signed_area(result.polygon))),
                           std::sqrt(std::abs(geometry::signed_area(truth.polygon)))));
      errors.push_back(rel(geometry::perimeter(result.polygon), geometry::perimeter(truth.polygon)));
    }
    return errors;
  }
  for (const auto& [name, value] : truth.dimensions) {
    for (const auto& [got_name, got] : result.dimensions) {
      if (got_name == name) errors.push_back(std::abs(got - value) / value);
    }
  }
  return errors;
}

void score_cloud(const TestCloud& cloud, const pipeline::RecognitionResult& r,
                 std::map<std::string, Tally>& tallies) {
  const std::vector<int> result_of = match_results(cloud, r);
  std::vector<bool> used(r.objects.size(), false);
  for (std::size_t t = 0; t < cloud.truths.size(); ++t) {
    const Truth& truth = cloud.truths[t];
    Tally& tally = tallies[truth.row.empty() ? truth.shape : truth.row];
    ++tally.objects;
    if (result_of[t] < 0) {
      ++tally.missed;
      ++tally.wrong_as["missed"];
      continue;
    }
    const pipeline::ObjectResult& got = r.objects[result_of[t]];
    used[result_of[t]] = true;
    ++tally.matched;
    if (got.shape != "unknown") ++tally.shaped;
    if (got.partial) ++tally.partial;
    if (!same_shape(truth, got)) {
      ++tally.wrong_as[got.shape == "prism" && got.shape == truth.shape
                           ? "prism of " + std::to_string(got.polygon.size()) + " sides"
                           : got.shape];
      continue;
    }
    ++tally.right;
    for (double e : dimension_errors(truth, got)) tally.dimension_errors.push_back(e);
    if (!truth.has_pose) continue;
    tally.centre_errors.push_back((got.center - truth.center).norm() / truth.size);
    for (const AxisCheck& check : truth.axis_checks) {
      tally.axis_errors_deg.push_back(angle_deg(got.axes.row(check.index).transpose(),
                                                truth.axes.row(check.index).transpose(),
                                                check.signed_direction));
    }
  }
  for (std::size_t o = 0; o < r.objects.size(); ++o) {
    if (used[o] || cloud.truths.empty()) continue;
    std::size_t nearest = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < cloud.truths.size(); ++t) {
      const double d = (r.objects[o].center - cloud.truths[t].center).norm();
      if (d < best) best = d, nearest = t;
    }
    const Truth& truth = cloud.truths[nearest];
    ++tallies[truth.row.empty() ? truth.shape : truth.row].false_objects;
  }
}

namespace {
constexpr const char* kUndetermined = "/undet";
}  // namespace

std::string undetermined_row(const std::string& shape) { return shape + kUndetermined; }

bool is_undetermined_row(const std::string& row) {
  const std::string suffix = kUndetermined;
  return row.size() >= suffix.size() && row.compare(row.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Tally merge(const std::map<std::string, Tally>& tallies, bool undetermined) {
  Tally all;
  const auto append = [](std::vector<double>& to, const std::vector<double>& from) {
    to.insert(to.end(), from.begin(), from.end());
  };
  for (const auto& [row, t] : tallies) {
    if (is_undetermined_row(row) != undetermined) continue;
    all.objects += t.objects;
    all.right += t.right;
    all.matched += t.matched;
    all.shaped += t.shaped;
    all.partial += t.partial;
    all.false_objects += t.false_objects;
    all.missed += t.missed;
    append(all.dimension_errors, t.dimension_errors);
    append(all.centre_errors, t.centre_errors);
    append(all.axis_errors_deg, t.axis_errors_deg);
    for (const auto& [name, n] : t.wrong_as) all.wrong_as[name] += n;
  }
  return all;
}

}  // namespace cloudshape::bench
