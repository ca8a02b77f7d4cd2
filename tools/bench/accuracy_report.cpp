// Table and JSON rendering of the accuracy benchmark's tallies.
// Errors print as percentages (of the true dimension, of the solid's size) and degrees.
#include "accuracy_report.hpp"

#include <string>

#include "bench_stats.hpp"
#include "synth/ground_truth.hpp"

namespace cloudshape::bench {

namespace {

// Rows in the fixed shape order, then whatever else a condition holds, then "all/undet" when some
// views do not determine their solid, and last "all" (the rest; readers take the last row).
std::vector<std::pair<std::string, Tally>> rows_of(const ConditionReport& c) {
  std::vector<std::pair<std::string, Tally>> rows;
  for (const auto kind : synth::all_shape_kinds()) {
    const auto it = c.tallies.find(synth::to_string(kind));
    if (it != c.tallies.end()) rows.emplace_back(it->first, it->second);
  }
  for (const auto& [shape, t] : c.tallies) {
    if (!synth::shape_kind_from_string(shape) && !is_undetermined_row(shape)) rows.emplace_back(shape, t);
  }
  for (const auto& [shape, t] : c.tallies) {
    if (is_undetermined_row(shape)) rows.emplace_back(shape, t);
  }
  const Tally undetermined = merge(c.tallies, true);
  if (undetermined.objects > 0) rows.emplace_back(undetermined_row("all"), undetermined);
  rows.emplace_back("all", merge(c.tallies));
  return rows;
}

double pct(int part, int whole) { return whole > 0 ? 100.0 * part / whole : 0.0; }

std::string fmt(const std::vector<double>& v, double q, double scale, const char* unit) {
  if (v.empty()) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f%s", percentile(v, q) * scale, unit);
  return buf;
}

std::string wrong_as(const Tally& t) {
  std::string s;
  for (const auto& [shape, n] : t.wrong_as) {
    s += (s.empty() ? "" : ", ") + shape + " " + std::to_string(n);
  }
  return s.empty() ? "-" : s;
}

nlohmann::ordered_json quantile_or_null(const std::vector<double>& v, double q) {
  return v.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(percentile(v, q));
}

nlohmann::ordered_json row_json(const std::string& shape, const Tally& t) {
  nlohmann::ordered_json j;
  j["shape"] = shape;
  j["objects"] = t.objects;
  j["right"] = t.right;
  j["recognized_pct"] = pct(t.right, t.objects);
  j["dimension_error"] = {{"median", quantile_or_null(t.dimension_errors, 0.5)},
                          {"p90", quantile_or_null(t.dimension_errors, 0.9)},
                          {"count", t.dimension_errors.size()}};
  j["centre_error_median"] = quantile_or_null(t.centre_errors, 0.5);
  j["axis_error_deg_median"] = quantile_or_null(t.axis_errors_deg, 0.5);
  j["false_objects"] = t.false_objects;
  j["missed_objects"] = t.missed;
  j["partial_pct"] = pct(t.partial, t.shaped);
  j["wrong_as"] = t.wrong_as;
  return j;
}

}  // namespace

std::string dimensions_text(const std::vector<std::pair<std::string, double>>& d) {
  std::string s;
  for (const auto& [name, v] : d) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%s %.4g", s.empty() ? "" : ", ", name.c_str(), v);
    s += buf;
  }
  return s.empty() ? "-" : s;
}

void print_accuracy_table(const std::vector<ConditionReport>& reports, std::FILE* out) {
  std::fprintf(out,
               "right%%: truths given the right shape. dim: relative error of every dimension of "
               "right-shape objects (median, p90).\nctr: centre error / solid size. axis: angle "
               "(box axes tying another within 3%% skipped; cylinder, prism sign-free; cone "
               "signed).\nfalse: results matched to no truth. missed: truths matched by no "
               "result. partial%%: matched results with a shape flagged partial.\n\n");
  std::fprintf(out, "%-12s %-17s %5s %7s %8s %8s %8s %9s %6s %6s %8s  %s\n", "condition", "shape",
               "objs", "right%", "dim_med", "dim_p90", "ctr_med", "axis_med", "false", "missed",
               "partial%", "wrong as");
  for (const auto& c : reports) {
    for (const auto& [shape, t] : rows_of(c)) {
      std::fprintf(out, "%-12s %-17s %5d %7.1f %8s %8s %8s %9s %6d %6d %8.1f  %s\n", c.name.c_str(),
                   shape.c_str(), t.objects, pct(t.right, t.objects),
                   fmt(t.dimension_errors, 0.5, 100, "%").c_str(),
                   fmt(t.dimension_errors, 0.9, 100, "%").c_str(),
                   fmt(t.centre_errors, 0.5, 100, "%").c_str(),
                   fmt(t.axis_errors_deg, 0.5, 1, "deg").c_str(), t.false_objects, t.missed,
                   pct(t.partial, t.shaped), wrong_as(t).c_str());
    }
  }
  for (const auto& c : reports) {
    if (c.samples.empty()) continue;
    std::fprintf(out, "\nreal samples (truth: SOURCES.md face-to-face; file units):\n");
    for (const auto& s : c.samples) {
      const std::string several =
          s.results > 1 ? "  (" + std::to_string(s.results) + " objects)" : "";
      std::fprintf(out, "  %-44s %-16s -> %-16s conf %.2f%s  truth {%s}  got {%s}%s\n",
                   s.label.c_str(), s.expected.c_str(), s.got.c_str(), s.confidence,
                   s.partial ? " partial" : "", dimensions_text(s.truth_dimensions).c_str(),
                   dimensions_text(s.got_dimensions).c_str(), several.c_str());
    }
  }
  std::fprintf(out, "\n");
  for (const auto& c : reports) {
    const Tally all = merge(c.tallies);
    std::fprintf(out,
                 "%s: %d/%d right shape (%.1f%%), dimension error median %s p90 %s, centre "
                 "%s of size, axis %s, %d false, %d missed, partial %.1f%%; %zu clouds in "
                 "%.1f s\n",
                 c.name.c_str(), all.right, all.objects, pct(all.right, all.objects),
                 fmt(all.dimension_errors, 0.5, 100, "%").c_str(),
                 fmt(all.dimension_errors, 0.9, 100, "%").c_str(),
                 fmt(all.centre_errors, 0.5, 100, "%").c_str(),
                 fmt(all.axis_errors_deg, 0.5, 1, " deg").c_str(), all.false_objects, all.missed,
                 pct(all.partial, all.shaped), c.clouds, c.seconds);
    const Tally undetermined = merge(c.tallies, true);
    if (undetermined.objects == 0) continue;
    const auto unknown = undetermined.wrong_as.find("unknown");
    const int honest = unknown == undetermined.wrong_as.end() ? 0 : unknown->second;
    std::fprintf(out,
                 "%s, views that do not determine their solid (scored apart): %d, right shape %d, "
                 "unknown %d, another shape named %d\n",
                 c.name.c_str(), undetermined.objects, undetermined.right, honest,
                 undetermined.objects - undetermined.right - honest);
  }
}

nlohmann::ordered_json accuracy_json(const std::vector<ConditionReport>& reports,
                                     const nlohmann::ordered_json& settings) {
  nlohmann::ordered_json out;
  out["settings"] = settings;
  out["conditions"] = nlohmann::ordered_json::array();
  for (const auto& c : reports) {
    nlohmann::ordered_json j;
    j["name"] = c.name;
    j["description"] = c.description;
    j["clouds"] = c.clouds;
    j["seconds"] = c.seconds;
    j["rows"] = nlohmann::ordered_json::array();
    for (const auto& [shape, t] : rows_of(c)) j["rows"].push_back(row_json(shape, t));
    if (!c.samples.empty()) {
      j["samples"] = nlohmann::ordered_json::array();
      for (const auto& s : c.samples) {
        nlohmann::ordered_json sj;
        sj["file"] = s.label;
        sj["expected"] = s.expected;
        sj["got"] = s.got;
        sj["confidence"] = s.confidence;
        sj["partial"] = s.partial;
        sj["results"] = s.results;
        for (const auto& [name, v] : s.truth_dimensions) sj["truth"][name] = v;
        sj["dimensions"] = nlohmann::ordered_json::object();
        for (const auto& [name, v] : s.got_dimensions) sj["dimensions"][name] = v;
        j["samples"].push_back(sj);
      }
    }
    out["conditions"].push_back(j);
  }
  return out;
}

}  // namespace cloudshape::bench
