// Accuracy scoring for cloudshape-bench --accuracy: truth objects, result matching, tallies.
// Everything here is pure bookkeeping over one cloud's truths and one RecognitionResult.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "pipeline/result.hpp"

namespace cloudshape::bench {

// One axis of a truth pose the result's axes[index] is compared with.
struct AxisCheck {
  int index = 0;
  bool signed_direction = false;  // only the cone's axis has a meaningful sign
};

// What one object in a test cloud really is. Dimensions use INTERFACE.md names; for a single
// view they are the extents the visible part shows.
struct Truth {
  std::string shape;
  std::string label;  // real samples: the object's name; empty for synthetic solids
  std::vector<std::pair<std::string, double>> dimensions;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();    // matching always; scored when has_pose
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // row i = axes[i]
  bool has_pose = true;
  std::vector<AxisCheck> axis_checks;
  double size = 1.0;  // characteristic size: the unit of centre error and of the match gate
  // prism only: the cross-section (any frame). Right needs the result's `sides` equal to its
  // corners; the dimension errors are the height's, the square root of the area's, the perimeter's.
  std::vector<Eigen::Vector2d> polygon;
  // The table row this truth is tallied in when not its shape's: a single view that does not
  // determine its solid (undetermined_row), scored apart from the views that do.
  std::string row;
};

// The row of a shape's views that do not determine it ("prism/undet"), and whether a row is
// one: such rows stay out of "all" and get an "all/undet" of their own.
std::string undetermined_row(const std::string& shape);
bool is_undetermined_row(const std::string& row);

struct TestCloud {
  std::string source;
  PointList points;
  std::vector<Truth> truths;
  // Multi-object clouds only match a result within 0.5 size of a truth; with one truth the
  // nearest result is its answer wherever it lies (its centre error then says how far).
  bool gate_matching = false;
  std::string note;  // how the cloud was made, for --per-cloud (e.g. the view angle)
};

// Everything one table row aggregates (one condition x one truth shape).
struct Tally {
  int objects = 0;
  int right = 0;
  int matched = 0;
  int shaped = 0;   // matched results with a shape: `unknown` never claims to be partial
  int partial = 0;  // shaped results flagged partial
  int false_objects = 0;
  int missed = 0;
  std::vector<double> dimension_errors;  // relative, every dimension of right-shape objects
  std::vector<double> centre_errors;     // |centre error| / size, right-shape objects with pose
  std::vector<double> axis_errors_deg;   // one per AxisCheck of right-shape objects
  std::map<std::string, int> wrong_as;   // result shape (or "missed") of wrong objects
};

// Per truth: the index of its result in r.objects, or -1 when missed.
std::vector<int> match_results(const TestCloud& cloud, const pipeline::RecognitionResult& r);

// Adds the cloud's objects to tallies[truth shape]; an unmatched result counts as a false
// object of the nearest truth's shape (it is usually a fragment or a ghost of that object).
void score_cloud(const TestCloud& cloud, const pipeline::RecognitionResult& r,
                 std::map<std::string, Tally>& tallies);

// The union of several tallies: the "all" row of the rows that are not undetermined ones, or
// (undetermined = true) of those that are.
Tally merge(const std::map<std::string, Tally>& tallies, bool undetermined = false);

// Relative error of each truth dimension the result also reports, by name (a prism: height,
// sqrt(area) and perimeter of its polygon).
std::vector<double> dimension_errors(const Truth& truth, const pipeline::ObjectResult& result);

// The result's shape is the truth's, and a prism's corner count too.
bool same_shape(const Truth& truth, const pipeline::ObjectResult& result);

}  // namespace cloudshape::bench
