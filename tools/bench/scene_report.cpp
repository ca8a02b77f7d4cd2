// Tallies and rendering of the scene benchmark: the readable table, per-scene lines, JSON.
// IoU prints as "n/a" while the recognizer reports no point indices.
#include "scene_report.hpp"

#include "bench_stats.hpp"

#include <algorithm>

namespace cloudshape::bench {

namespace {

void add(SceneTally& t, const SceneRun& r) {
  const SceneScore& s = r.score;
  ++t.scenes;
  t.objects += static_cast<int>(s.objects.size());
  t.right += s.right;
  t.wrong_shape += s.wrong_shape;
  t.missed += s.missed;
  t.false_objects += s.false_objects;
  t.duplicates += s.duplicates;
  t.table += s.table;
  for (const auto& o : s.objects) {
    if (o.iou >= 0.0) t.ious.push_back(o.iou);
    if (o.outcome != ObjectOutcome::wrong_shape) continue;
    for (const auto& shape : o.reported_shapes) ++t.wrong_as[shape];
  }
  t.wall_ms.push_back(r.wall_ms);
  t.total_ms.push_back(r.total_ms);
  t.cpu_ms.push_back(r.cpu_ms);
}

double pct(int part, int whole) { return whole > 0 ? 100.0 * part / whole : 0.0; }
double per_scene(int n, int scenes) { return scenes > 0 ? static_cast<double>(n) / scenes : 0.0; }

double mean_of(const std::vector<double>& v) {
  double sum = 0.0;
  for (const double x : v) sum += x;
  return v.empty() ? 0.0 : sum / static_cast<double>(v.size());
}

std::string iou_text(const SceneTally& t) {
  if (t.ious.empty()) return "n/a";
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.3f", mean_of(t.ious));
  return buf;
}

std::string wrong_as_text(const std::map<std::string, int>& wrong_as) {
  std::string s;
  for (const auto& [shape, n] : wrong_as)
    s += (s.empty() ? "" : ", ") + shape + " " + std::to_string(n);
  return s.empty() ? "-" : s;
}

nlohmann::ordered_json row_json(const std::string& category, const SceneTally& t) {
  nlohmann::ordered_json j;
  j["category"] = category;
  j["scenes"] = t.scenes;
  j["objects"] = t.objects;
  j["right"] = t.right;
  j["right_pct"] = pct(t.right, t.objects);
  j["wrong_shape"] = t.wrong_shape;
  j["missed"] = t.missed;
  j["false_objects"] = t.false_objects;
  j["false_per_scene"] = per_scene(t.false_objects, t.scenes);
  j["duplicates"] = t.duplicates;
  j["table_objects"] = t.table;
  j["iou_mean"] =
      t.ious.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(mean_of(t.ious));
  j["iou_objects"] = t.ious.size();
  j["wall_ms"] = {{"median", median_of(t.wall_ms)}, {"max", max_of(t.wall_ms)}};
  j["total_ms"] = {{"median", median_of(t.total_ms)}, {"max", max_of(t.total_ms)}};
  j["cpu_ms"] = {{"median", median_of(t.cpu_ms)}, {"max", max_of(t.cpu_ms)}};
  j["wrong_as"] = t.wrong_as;
  return j;
}

}  // namespace

double median_of(std::vector<double> v) { return percentile(std::move(v), 0.5); }

double max_of(const std::vector<double>& v) { return summarize(v).max; }

std::vector<std::pair<std::string, SceneTally>> tally_scenes(
    const std::vector<SceneRun>& runs, const std::vector<std::string>& category_order) {
  std::map<std::string, SceneTally> by_category;
  SceneTally all;
  for (const auto& r : runs) {
    add(by_category[r.category], r);
    add(all, r);
  }
  std::vector<std::pair<std::string, SceneTally>> rows;
  for (const auto& c : category_order) {
    const auto it = by_category.find(c);
    if (it == by_category.end()) continue;
    rows.emplace_back(c, it->second);
    by_category.erase(it);
  }
  for (const auto& [c, t] : by_category) rows.emplace_back(c, t);
  rows.emplace_back("all", all);
  return rows;
}

std::string med_max(const std::vector<double>& v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f/%.0f", median_of(v), max_of(v));
  return buf;
}

void print_scene_table(const std::vector<std::pair<std::string, SceneTally>>& rows,
                       std::FILE* out) {
  std::fprintf(out,
               "objects: labelled objects (the parts of one occluded object count once). right: "
               "a report on it has an accepted shape.\nfalse: reports on no labelled object and "
               "not the table. dup: a second report on one label group. table: reports on the "
               "table (or other structure: labels 1-9).\nIoU: mean point overlap of matched "
               "objects (n/a without point indices). "
               "ms per frame (median/max): the pipeline's total, wall clock, CPU time.\n\n");
  std::fprintf(out, "%-14s %6s %7s %6s %7s %6s %6s %6s %7s %5s %6s %6s %9s %9s %9s  %s\n",
               "category", "scenes", "objects", "right", "right%", "wrong", "missed", "false",
               "false/s", "dup", "table", "IoU", "total ms", "wall ms", "cpu ms", "wrong as");
  for (const auto& [category, t] : rows) {
    std::fprintf(out, "%-14s %6d %7d %6d %7.1f %6d %6d %6d %7.2f %5d %6d %6s %9s %9s %9s  %s\n",
                 category.c_str(), t.scenes, t.objects, t.right, pct(t.right, t.objects),
                 t.wrong_shape, t.missed, t.false_objects, per_scene(t.false_objects, t.scenes),
                 t.duplicates, t.table, iou_text(t).c_str(), med_max(t.total_ms).c_str(),
                 med_max(t.wall_ms).c_str(), med_max(t.cpu_ms).c_str(),
                 wrong_as_text(t.wrong_as).c_str());
  }
}

void print_scene_lines(const std::vector<SceneRun>& runs, std::FILE* out) {
  for (const auto& r : runs) {
    std::string objects;
    for (const auto& o : r.score.objects) {
      std::string got;
      for (const auto& s : o.reported_shapes) got += (got.empty() ? "" : "+") + s;
      objects += " " + std::to_string(o.object * 10) + ":" + to_string(o.outcome) +
                 (got.empty() ? "" : "(" + got + ")");
    }
    std::string reports;
    for (std::size_t k = 0; k < r.score.reports.size(); ++k) {
      const ReportScore& s = r.score.reports[k];
      reports += " " + r.reported[k].shape + "->" + to_string(s.kind) +
                 (s.label != 0 ? "@" + std::to_string(s.label) : "");
    }
    std::fprintf(out, "%-14s %-14s %6.0f ms  labelled:%s  reported:%s\n", r.file.c_str(),
                 r.category.c_str(), r.wall_ms, objects.empty() ? " -" : objects.c_str(),
                 reports.empty() ? " -" : reports.c_str());
  }
}

nlohmann::ordered_json scenes_json(const std::vector<SceneRun>& runs,
                                   const std::vector<std::pair<std::string, SceneTally>>& rows,
                                   const nlohmann::ordered_json& settings) {
  nlohmann::ordered_json out;
  out["settings"] = settings;
  out["rows"] = nlohmann::ordered_json::array();
  for (const auto& [category, t] : rows) out["rows"].push_back(row_json(category, t));
  out["scenes"] = nlohmann::ordered_json::array();
  for (const auto& r : runs) {
    nlohmann::ordered_json j;
    j["file"] = r.file;
    j["category"] = r.category;
    j["truth"] = r.truth;
    j["points"] = r.points;
    j["organized"] = r.organized;
    j["wall_ms"] = r.wall_ms;
    j["total_ms"] = r.total_ms;
    j["cpu_ms"] = r.cpu_ms;
    j["objects"] = nlohmann::ordered_json::array();
    for (const auto& o : r.score.objects) {
      nlohmann::ordered_json oj;
      oj["object"] = o.object;
      oj["parts"] = o.parts;
      oj["points"] = o.points;
      oj["outcome"] = to_string(o.outcome);
      oj["reported_shapes"] = o.reported_shapes;
      oj["iou"] = o.iou >= 0.0 ? nlohmann::ordered_json(o.iou) : nlohmann::ordered_json(nullptr);
      j["objects"].push_back(oj);
    }
    j["reports"] = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < r.score.reports.size(); ++k) {
      const ReportScore& s = r.score.reports[k];
      nlohmann::ordered_json rj;
      rj["shape"] = r.reported[k].shape;
      rj["confidence"] = r.reported[k].confidence;
      rj["kind"] = to_string(s.kind);
      rj["label"] =
          s.label != 0 ? nlohmann::ordered_json(s.label) : nlohmann::ordered_json(nullptr);
      rj["by_centre"] = s.by_centre;
      if (!s.by_centre) rj["share"] = s.share;
      j["reports"].push_back(rj);
    }
    out["scenes"].push_back(j);
  }
  return out;
}

}  // namespace cloudshape::bench
