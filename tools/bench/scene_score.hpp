// cloudshape-bench --scenes: scores one scene's reported objects against its per-point labels
// (which reported object is which labelled object, right shape or not, segmentation overlap).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "pipeline/result.hpp"
#include "scene_truth.hpp"

namespace cloudshape::bench {

// Label groups smaller than this are ignored: neither required nor matched (SOURCES.md).
constexpr std::size_t kMinGroupPoints = 50;

// What the scorer needs of a reported object.
struct ReportedObject {
  std::string shape;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double diameter = 0.0;  // the solid's largest span from its dimensions; 0 when unknown
  std::vector<std::uint32_t> point_indices;  // into the scene's points; may be empty
};

ReportedObject reported_object(const pipeline::ObjectResult& r);

// How one reported object was counted.
enum class ReportKind {
  match,          // the first (best) report on a label group
  duplicate,      // another report on a group already matched: over-segmentation
  table,          // the table (structure): neither an object nor a false object
  ignored_group,  // a label group under kMinGroupPoints: not scored
  false_object,   // no label group
};
const char* to_string(ReportKind k);

struct ReportScore {
  ReportKind kind = ReportKind::false_object;
  std::uint32_t label = 0;  // the group it fell on (match, duplicate, ignored_group)
  bool by_centre = false;   // no point_indices: placed by the centre rule
  double share = 0.0;       // with indices: the fraction of its points in that group
};

enum class ObjectOutcome { right, wrong_shape, missed };
const char* to_string(ObjectOutcome o);

struct ObjectScore {
  std::uint32_t object = 0;          // label / 10
  std::vector<std::uint32_t> parts;  // its labels of at least kMinGroupPoints points
  std::size_t points = 0;
  ObjectOutcome outcome = ObjectOutcome::missed;
  std::vector<std::string> reported_shapes;  // of the reports matched to its parts
  double iou = -1.0;  // points of the matched reports vs its parts; -1 when not measurable
};

struct SceneScore {
  std::vector<ObjectScore> objects;  // by object number
  std::vector<ReportScore> reports;  // in the order of the reported objects
  int right = 0;
  int wrong_shape = 0;
  int missed = 0;
  int false_objects = 0;
  int duplicates = 0;
  int table = 0;
};

// Scores `reported` against `labels` (one per point of `points`). Rules:
// - Groups: every label >= 20 with at least kMinGroupPoints points is a part; the parts of one
//   object (same label / 10) are one labelled object. Labels 1-9 together are the table.
// - A report with point_indices falls on what holds more than half of its (distinct) points:
//   an object (all its parts together; it then claims the part it shares most points with),
//   the table, or only parts under the floor (not scored); without such a majority, or with
//   one of label 0 / 10-19, it is a false object.
// - A report without point_indices falls by its centre: on the object part whose nearest point
//   is closest to the centre, if that distance is at most half the part's size and the report's
//   diameter at most twice that size (size = sqrt(12) x the RMS distance of the part's points
//   from their centroid: a filled box's diagonal); else on the table under the same two tests
//   and a diameter of at least half the table's size (a report that is the table spans much
//   of it); else it is a false object.
// - A part matched by several reports keeps the one sharing most points with it (by centre:
//   the nearest); the others are duplicates. An object is right when any report matched to
//   any of its parts has an accepted shape, wrong_shape when matched but none has, else
//   missed. Reports on an object's other parts are not duplicates (mOSD's convention: an
//   occluded object may come out in pieces).
// - IoU of a matched object: its parts' points against the union of the point_indices of
//   its matched reports; not measurable (-1) when any of those has no indices.
// Throws std::invalid_argument when labels and points differ in size, when an index is out
// of range, or when `truth` gives no accepted shape for a labelled object (naming it).
SceneScore score_scene(const PointList& points, const std::vector<std::uint32_t>& labels,
                       const SceneTruth& truth, const std::vector<ReportedObject>& reported);

}  // namespace cloudshape::bench
