// The scene scorer: label groups, report placement (by points or by centre), matching,
// per-object outcome and IoU. The rules are spelled out in scene_score.hpp.
#include "scene_score.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace cloudshape::bench {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Group {
  std::vector<std::uint32_t> indices;
  double size = 0.0;  // sqrt(12) x RMS distance from the centroid
};

double group_size(const PointList& points, const std::vector<std::uint32_t>& indices) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto i : indices) mean += points[i];
  mean /= static_cast<double>(indices.size());
  double sq = 0.0;
  for (const auto i : indices) sq += (points[i] - mean).squaredNorm();
  return std::sqrt(12.0 * sq / static_cast<double>(indices.size()));
}

double nearest_distance(const PointList& points, const std::vector<std::uint32_t>& indices,
                        const Eigen::Vector3d& c) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto i : indices) best = std::min(best, (points[i] - c).squaredNorm());
  return std::sqrt(best);
}

double dimension(const pipeline::ObjectResult& r, const char* name) {
  for (const auto& [n, v] : r.dimensions) {
    if (n == name) return v;
  }
  return 0.0;
}

// Where one report fell, before duplicates are told apart.
struct Placement {
  ReportScore score;
  double rank = 0.0;  // larger is a better claim on the group
};

// What a label votes for: its object (all parts together: a report joining an occluded
// object's pieces is that object), the table (labels 1-9 as one), or itself.
std::uint32_t voter(std::uint32_t label) {
  if (is_object_label(label)) return object_of_label(label);
  return is_structure_label(label) ? 1 : label;
}

Placement place_by_points(const ReportedObject& r, const std::vector<std::uint32_t>& labels,
                          const std::map<std::uint32_t, Group>& parts) {
  std::vector<std::uint32_t> idx = r.point_indices;
  std::sort(idx.begin(), idx.end());
  idx.erase(std::unique(idx.begin(), idx.end()), idx.end());
  std::map<std::uint32_t, std::size_t> per_label;
  for (const auto i : idx) ++per_label[labels[i]];
  // Object votes are kept apart from the others: object 1 would otherwise be the table.
  std::map<std::pair<bool, std::uint32_t>, std::size_t> votes;
  for (const auto& [l, n] : per_label) votes[{is_object_label(l), voter(l)}] += n;
  const auto top = std::max_element(
      votes.begin(), votes.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  Placement p;
  p.score.share = static_cast<double>(top->second) / static_cast<double>(idx.size());
  if (2 * top->second <= idx.size()) return p;  // no majority: false object
  const auto [is_object, who] = top->first;
  if (!is_object) {
    p.score.kind = who == 1 ? ReportKind::table : ReportKind::false_object;
    return p;
  }
  // The object's part it shares most points with is the group it claims.
  for (const auto& [l, n] : per_label) {
    if (!is_object_label(l) || object_of_label(l) != who || parts.count(l) == 0) continue;
    if (static_cast<double>(n) > p.rank) {
      p.rank = static_cast<double>(n);
      p.score.label = l;
    }
  }
  p.score.kind = p.score.label != 0 ? ReportKind::match : ReportKind::ignored_group;
  return p;
}

bool fits(double distance, double diameter, const Group& g) {
  return distance <= 0.5 * g.size && (diameter <= 0.0 || diameter <= 2.0 * g.size);
}

Placement place_by_centre(const ReportedObject& r, const PointList& points,
                          const std::map<std::uint32_t, Group>& parts,
                          const std::map<std::uint32_t, Group>& small, const Group& table) {
  Placement p;
  p.score.by_centre = true;
  double best = std::numeric_limits<double>::infinity();
  std::uint32_t best_label = 0;
  bool best_small = false;
  for (const auto* groups : {&parts, &small}) {
    for (const auto& [label, g] : *groups) {
      const double d = nearest_distance(points, g.indices, r.center);
      if (d < best && fits(d, r.diameter, g)) {
        best = d;
        best_label = label;
        best_small = groups == &small;
      }
    }
  }
  if (best_label != 0) {
    p.score.label = best_label;
    p.score.kind = best_small ? ReportKind::ignored_group : ReportKind::match;
    p.rank = -best;
    return p;
  }
  if (!table.indices.empty()) {
    const double d = nearest_distance(points, table.indices, r.center);
    if (fits(d, r.diameter, table) && (r.diameter <= 0.0 || r.diameter >= 0.5 * table.size))
      p.score.kind = ReportKind::table;
  }
  return p;
}

}  // namespace

ReportedObject reported_object(const pipeline::ObjectResult& r) {
  ReportedObject o;
  o.shape = r.shape;
  o.center = r.center;
  o.point_indices = r.point_indices;
  const double h = dimension(r, "height");
  const double radius = dimension(r, "radius");
  const auto span = [](double across, double along) { return std::hypot(across, along); };
  if (r.shape == "box") {
    o.diameter = std::hypot(dimension(r, "length"), dimension(r, "width"), h);
  } else if (r.shape == "cylinder" || r.shape == "cone" || r.shape == "frustum") {
    o.diameter = span(2.0 * radius, h);
  } else if (r.shape == "sphere") {
    o.diameter = 2.0 * radius;
  } else if (r.shape == "tetrahedron") {
    o.diameter = dimension(r, "edge");
  } else if (r.shape == "pentagonal_prism") {
    o.diameter = span(dimension(r, "side") / std::sin(kPi / 5.0), h);
  } else if (r.shape == "prism" && dimension(r, "sides") >= 3.0 && dimension(r, "side") > 0.0) {
    o.diameter = span(dimension(r, "side") / std::sin(kPi / dimension(r, "sides")), h);
  }
  return o;
}

const char* to_string(ReportKind k) {
  switch (k) {
    case ReportKind::match:
      return "match";
    case ReportKind::duplicate:
      return "duplicate";
    case ReportKind::table:
      return "table";
    case ReportKind::ignored_group:
      return "ignored_group";
    case ReportKind::false_object:
      return "false_object";
  }
  return "?";
}

const char* to_string(ObjectOutcome o) {
  switch (o) {
    case ObjectOutcome::right:
      return "right";
    case ObjectOutcome::wrong_shape:
      return "wrong_shape";
    case ObjectOutcome::missed:
      return "missed";
  }
  return "?";
}

SceneScore score_scene(const PointList& points, const std::vector<std::uint32_t>& labels,
                       const SceneTruth& truth, const std::vector<ReportedObject>& reported) {
  if (labels.size() != points.size())
    throw std::invalid_argument("scene has " + std::to_string(points.size()) + " points but " +
                                std::to_string(labels.size()) + " labels");
  std::map<std::uint32_t, Group> parts;  // label -> points, labels >= 20 big enough
  std::map<std::uint32_t, Group> small;  // labels >= 20 under kMinGroupPoints
  Group table;
  for (std::uint32_t i = 0; i < labels.size(); ++i) {
    if (is_object_label(labels[i])) parts[labels[i]].indices.push_back(i);
    if (is_structure_label(labels[i])) table.indices.push_back(i);
  }
  for (auto it = parts.begin(); it != parts.end();) {
    it->second.size = group_size(points, it->second.indices);
    if (it->second.indices.size() < kMinGroupPoints) {
      small.insert(*it);
      it = parts.erase(it);
    } else {
      ++it;
    }
  }
  if (!table.indices.empty()) table.size = group_size(points, table.indices);

  SceneScore score;
  std::map<std::uint32_t, std::size_t> object_slot;
  for (const auto& [label, g] : parts) {
    const std::uint32_t object = object_of_label(label);
    if (object_slot.count(object) == 0) {
      if (truth.accepted_shapes(object).empty())
        throw std::invalid_argument("the truth gives no shape for object label " +
                                    std::to_string(label) + " (" +
                                    std::to_string(g.indices.size()) + " points)");
      object_slot[object] = score.objects.size();
      score.objects.push_back(ObjectScore{object, {}, 0, ObjectOutcome::missed, {}, -1.0});
    }
    ObjectScore& o = score.objects[object_slot[object]];
    o.parts.push_back(label);
    o.points += g.indices.size();
  }

  std::vector<Placement> placed;
  for (const auto& r : reported) {
    for (const auto i : r.point_indices) {
      if (i >= points.size())
        throw std::invalid_argument("a reported object's point index " + std::to_string(i) +
                                    " is beyond the scene's " + std::to_string(points.size()) +
                                    " points");
    }
    placed.push_back(r.point_indices.empty() ? place_by_centre(r, points, parts, small, table)
                                             : place_by_points(r, labels, parts));
  }
  // Per part, the best claim wins; reports placed by points outrank those placed by centre.
  std::map<std::uint32_t, std::size_t> winner;
  const auto better = [&](std::size_t a, std::size_t b) {
    if (placed[a].score.by_centre != placed[b].score.by_centre) return !placed[a].score.by_centre;
    return placed[a].rank > placed[b].rank;
  };
  for (std::size_t k = 0; k < placed.size(); ++k) {
    if (placed[k].score.kind != ReportKind::match) continue;
    const auto [it, first] = winner.emplace(placed[k].score.label, k);
    if (!first && better(k, it->second)) it->second = k;
  }
  for (std::size_t k = 0; k < placed.size(); ++k) {
    ReportScore s = placed[k].score;
    if (s.kind == ReportKind::match && winner.at(s.label) != k) s.kind = ReportKind::duplicate;
    score.reports.push_back(s);
    score.false_objects += s.kind == ReportKind::false_object;
    score.duplicates += s.kind == ReportKind::duplicate;
    score.table += s.kind == ReportKind::table;
  }

  for (auto& o : score.objects) {
    std::vector<std::size_t> matched;
    for (const auto label : o.parts) {
      const auto it = winner.find(label);
      if (it != winner.end()) matched.push_back(it->second);
    }
    const auto& accepted = truth.accepted_shapes(o.object);
    for (const auto k : matched) {
      o.reported_shapes.push_back(reported[k].shape);
      if (std::find(accepted.begin(), accepted.end(), reported[k].shape) != accepted.end())
        o.outcome = ObjectOutcome::right;
    }
    if (!matched.empty() && o.outcome != ObjectOutcome::right)
      o.outcome = ObjectOutcome::wrong_shape;
    score.right += o.outcome == ObjectOutcome::right;
    score.wrong_shape += o.outcome == ObjectOutcome::wrong_shape;
    score.missed += o.outcome == ObjectOutcome::missed;

    const bool measurable =
        !matched.empty() && std::all_of(matched.begin(), matched.end(), [&](std::size_t k) {
          return !reported[k].point_indices.empty();
        });
    if (!measurable) continue;
    std::vector<std::uint32_t> seg;
    for (const auto k : matched)
      seg.insert(seg.end(), reported[k].point_indices.begin(), reported[k].point_indices.end());
    std::sort(seg.begin(), seg.end());
    seg.erase(std::unique(seg.begin(), seg.end()), seg.end());
    std::size_t inter = 0;
    for (const auto i : seg) {
      inter += object_of_label(labels[i]) == o.object && parts.count(labels[i]) > 0;
    }
    o.iou = static_cast<double>(inter) / static_cast<double>(seg.size() + o.points - inter);
  }
  return score;
}

}  // namespace cloudshape::bench
