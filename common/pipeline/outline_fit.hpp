// A flat face's outline as the polygon its border points tell: each side's line refitted to the
// border points nearest it, and sides the points cannot tell apart (a ragged border's bends) joined.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace cloudshape::pipeline::detail {

// One side of a counter-clockwise outline: the line n.x = d, n outward. Side k and side k+1
// meet at corner k.
struct OutlineSide {
  Eigen::Vector2d n = Eigen::Vector2d::UnitX();
  double d = 0.0;
  bool fixed = false;                   // placed by a face seen along it: kept where it is
  int label = -1;                       // the caller's; a side joined to a fixed one keeps that one's
  std::vector<Eigen::Vector2d> points;  // out: the border points nearest this side
  Eigen::Vector2d end = Eigen::Vector2d::Zero();  // out: corner k, where side k+1 begins
};

struct OutlineFitParameters {
  double cell = 1.0;            // the outline grid's cell (the face's units): the scale of everything below
  double band_cells = 2.0;      // border points farther than this from the outline are the face's inside
  double end_cells = 1.0;       // points this near a side's ends are left out of its line (rounded corners);
                                // one cell, the grid's own rounding, so not a configuration key
  double min_length_cells = 3;  // a side no face shows that is shorter is a rounded corner: dropped
  double join_evidence = 2.0;   // two sides are one unless apart they fit their points better by more
                                // than this many noise variances per point's log (2: BIC, a line's two parameters)
};

// Refits the sides not fixed to the border points, drops those too short or with too few points
// to place, and joins neighbours whose points one line fits within the evidence (the join that
// costs least first), until every side stands. Fewer than three sides: empty.
std::vector<OutlineSide> fit_outline_sides(std::vector<OutlineSide> sides, const std::vector<Eigen::Vector2d>& border,
                                           const OutlineFitParameters& p);

}  // namespace cloudshape::pipeline::detail
