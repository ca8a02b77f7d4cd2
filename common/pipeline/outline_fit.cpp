// A flat face's outline refined on its border points: sides refitted, spurious bends dropped or
// joined by the evidence their points give (a two-line model against one, in noise variances).
#include "pipeline/outline_fit.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace cloudshape::pipeline::detail {
namespace {

constexpr std::size_t kMinPoints = 4;  // a line's two parameters, and two more to check them

std::optional<Eigen::Vector2d> meet(const OutlineSide& a, const OutlineSide& b) {
  Eigen::Matrix2d m;
  m.row(0) = a.n.transpose();
  m.row(1) = b.n.transpose();
  // Sides within about a degree of parallel meet too far off to place a corner.
  if (std::abs(m.determinant()) < 0.02) return std::nullopt;
  return m.inverse() * Eigen::Vector2d(a.d, b.d);
}

Eigen::Vector2d on_line(const OutlineSide& s, const Eigen::Vector2d& p) { return p - (p.dot(s.n) - s.d) * s.n; }

// Corner k joins side k and side k+1; where they are near parallel, the point midway between
// the two lines nearest the corner as it was.
std::vector<Eigen::Vector2d> corners_of(const std::vector<OutlineSide>& sides, const std::vector<Eigen::Vector2d>& was) {
  std::vector<Eigen::Vector2d> c(sides.size());
  for (std::size_t k = 0; k < sides.size(); ++k) {
    const OutlineSide& a = sides[k];
    const OutlineSide& b = sides[(k + 1) % sides.size()];
    if (auto m = meet(a, b)) c[k] = *m;
    else c[k] = 0.5 * (on_line(a, was[k]) + on_line(b, was[k]));
  }
  return c;
}

double segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - a - t * ab).norm();
}

// Each border point to the side whose segment is nearest, within the band (the later side on a
// tie). Only a side whose segment's box, widened by the band, holds the point can be within the
// band of it: a grid of cells lists, in side order, the sides whose widened box meets each cell,
// and a point tries those of its cell alone, in that order, so the answer is the one trying every
// side gives (a ragged outline has dozens of sides, and the fit assigns every border point a few
// times per side it drops). Among those, a side whose box lies farther than the best distance so
// far along either axis cannot be nearer either: skipped (a whisker over, so rounding never skips
// one that would win).
void assign(std::vector<OutlineSide>& sides, const std::vector<Eigen::Vector2d>& corners,
            const std::vector<Eigen::Vector2d>& border, double band) {
  const std::size_t n = sides.size();
  for (auto& s : sides) s.points.clear();
  struct Segment {
    Eigen::Vector2d a, b, lo, hi;
  };
  constexpr double kWhisker = 1.0 + 1e-9;
  const double reach = band * kWhisker;
  std::vector<Segment> segments(n);
  const Eigen::Vector2d widen = Eigen::Vector2d::Constant(reach);
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  // A segment with a corner at infinity or NaN is within the band of no point: never listed.
  std::vector<char> finite(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d& a = corners[(k + n - 1) % n];
    const Eigen::Vector2d& b = corners[k];
    segments[k] = Segment{a, b, a.cwiseMin(b), a.cwiseMax(b)};
    finite[k] = a.allFinite() && b.allFinite();
    if (!finite[k]) continue;
    lo = lo.cwiseMin(segments[k].lo - widen);
    hi = hi.cwiseMax(segments[k].hi + widen);
  }
  if (std::find(finite.begin(), finite.end(), 1) == finite.end()) return;
  // Cells no smaller than the band, at most kCells + 1 a side: a point's cell is its whole search.
  // Extents beyond what a double's cell count holds take one cell (every side tried).
  constexpr double kCells = 32.0;
  double cell = std::max(band, (hi - lo).maxCoeff() / kCells);
  if (!(cell > 0.0) || !std::isfinite(cell)) cell = std::numeric_limits<double>::infinity();
  const bool grid = std::isfinite(cell);
  const auto cells_x = grid ? static_cast<std::size_t>((hi.x() - lo.x()) / cell) + 1 : 1;
  const auto cells_y = grid ? static_cast<std::size_t>((hi.y() - lo.y()) / cell) + 1 : 1;
  const auto cell_of = [&](double x, double y) {
    if (!grid) return std::pair<std::size_t, std::size_t>{0, 0};
    const auto cx = std::min(cells_x - 1, static_cast<std::size_t>(std::max(0.0, (x - lo.x()) / cell)));
    const auto cy = std::min(cells_y - 1, static_cast<std::size_t>(std::max(0.0, (y - lo.y()) / cell)));
    return std::pair<std::size_t, std::size_t>{cx, cy};
  };
  std::vector<std::uint32_t> begin(cells_x * cells_y + 1, 0), listed;
  for (int fill = 0; fill < 2; ++fill) {
    std::vector<std::uint32_t> next(begin.begin(), begin.end() - 1);
    for (std::size_t k = 0; k < n; ++k) {
      if (!finite[k]) continue;
      const auto [x0, y0] = cell_of(segments[k].lo.x() - reach, segments[k].lo.y() - reach);
      const auto [x1, y1] = cell_of(segments[k].hi.x() + reach, segments[k].hi.y() + reach);
      for (std::size_t cy = y0; cy <= y1; ++cy)
        for (std::size_t cx = x0; cx <= x1; ++cx) {
          if (fill == 0) ++begin[cy * cells_x + cx + 1];
          else listed[next[cy * cells_x + cx]++] = static_cast<std::uint32_t>(k);
        }
    }
    if (fill == 0) {
      for (std::size_t c = 0; c + 1 < begin.size(); ++c) begin[c + 1] += begin[c];
      listed.resize(begin.back());
    }
  }
  for (const auto& p : border) {
    if (grid && !(p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y())) continue;
    const auto [cx, cy] = cell_of(p.x(), p.y());
    const std::size_t c = cy * cells_x + cx;
    std::size_t best = n;
    double best_d = band;
    for (std::uint32_t e = begin[c]; e < begin[c + 1]; ++e) {
      const std::size_t k = listed[e];
      const Segment& s = segments[k];
      const double r = best_d * kWhisker;
      if (p.x() < s.lo.x() - r || p.x() > s.hi.x() + r || p.y() < s.lo.y() - r || p.y() > s.hi.y() + r) continue;
      const double d = segment_distance(p, s.a, s.b);
      if (d <= best_d) best = k, best_d = d;
    }
    if (best < n) sides[best].points.push_back(p);
  }
}

struct Line {
  Eigen::Vector2d n;
  double d;
};

// Total least squares, the normal turned to `outward`.
std::optional<Line> tls(const std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& outward) {
  if (pts.size() < kMinPoints) return std::nullopt;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const auto& p : pts) cov.noalias() += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(cov);
  Eigen::Vector2d n = solver.eigenvectors().col(0).normalized();
  if (n.dot(outward) < 0.0) n = -n;
  return Line{n, n.dot(mean)};
}

double rss(const std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& n, double d) {
  double s = 0.0;
  for (const auto& p : pts) s += (p.dot(n) - d) * (p.dot(n) - d);
  return s;
}

// An unfixed side's line from its points away from its ends (a rounded corner bends them), or
// from all of them on a short side; kept where the points cannot place it, or would turn it
// more than 60 degrees (they are another side's).
void refit(std::vector<OutlineSide>& sides, const std::vector<Eigen::Vector2d>& corners, double end_gap) {
  const std::size_t n = sides.size();
  for (std::size_t k = 0; k < n; ++k) {
    OutlineSide& s = sides[k];
    if (s.fixed) continue;
    const Eigen::Vector2d a = corners[(k + n - 1) % n], b = corners[k];
    const double len = (b - a).norm();
    std::vector<Eigen::Vector2d> inner;
    if (len > 4.0 * end_gap) {
      const Eigen::Vector2d dir = (b - a) / len;
      for (const auto& p : s.points) {
        const double t = (p - a).dot(dir);
        if (t >= end_gap && t <= len - end_gap) inner.push_back(p);
      }
    }
    const auto line = tls(inner.size() >= kMinPoints ? inner : s.points, s.n);
    if (line && line->n.dot(s.n) >= 0.5) s.n = line->n, s.d = line->d;
  }
}

double noise_sigma(const std::vector<OutlineSide>& sides, double floor) {
  std::vector<double> r;
  for (const auto& s : sides)
    for (const auto& p : s.points) r.push_back(std::abs(p.dot(s.n) - s.d));
  if (r.empty()) return floor;
  auto mid = r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2);
  std::nth_element(r.begin(), mid, r.end());
  return std::max(floor, 1.4826 * *mid);
}

// Signed length of side k between its corners, along its counter-clockwise tangent: negative
// when its neighbours cross before reaching it.
double side_length(const std::vector<OutlineSide>& sides, const std::vector<Eigen::Vector2d>& corners, std::size_t k) {
  const std::size_t n = sides.size();
  const Eigen::Vector2d tangent(-sides[k].n.y(), sides[k].n.x());
  return (corners[k] - corners[(k + n - 1) % n]).dot(tangent);
}

// The short side to drop, or none: one shorter than min_length (the grid's rounding of a corner)
// or with too few points to place it. Its neighbours must meet for it to go; the shortest first.
std::optional<std::size_t> side_to_drop(const std::vector<OutlineSide>& sides, const std::vector<Eigen::Vector2d>& corners,
                                        double min_length) {
  const std::size_t n = sides.size();
  std::optional<std::size_t> best;
  double best_len = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < n; ++k) {
    if (sides[k].fixed) continue;
    const double len = side_length(sides, corners, k);
    const bool unplaced = sides[k].points.size() < kMinPoints && len < 2.0 * min_length;
    if (!(len < min_length) && !unplaced) continue;
    if (!meet(sides[(k + n - 1) % n], sides[(k + 1) % n])) continue;
    if (len < best_len) best = k, best_len = len;
  }
  return best;
}

struct Join {
  std::size_t at;
  Eigen::Vector2d n;
  double d;
};

// The neighbours one line fits about as well as two (BIC-like: the extra line must buy more
// than `evidence` noise variances per log of the points; parallel neighbours a step smaller than
// the band always join), the cheapest first.
std::optional<Join> pair_to_join(const std::vector<OutlineSide>& sides, double sigma, double evidence, double band) {
  const std::size_t n = sides.size();
  std::optional<Join> best;
  double best_excess = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const OutlineSide& a = sides[i];
    const OutlineSide& b = sides[(i + 1) % n];
    if (a.fixed && b.fixed) continue;
    std::vector<Eigen::Vector2d> pts = a.points;
    pts.insert(pts.end(), b.points.begin(), b.points.end());
    if (pts.size() < kMinPoints) continue;
    Line joint{a.n, a.d};
    if (a.fixed || b.fixed) {
      joint = a.fixed ? Line{a.n, a.d} : Line{b.n, b.d};
    } else {
      const auto l = tls(pts, a.n + b.n);
      if (!l) continue;
      joint = *l;
    }
    const double apart = rss(a.points, a.n, a.d) + rss(b.points, b.n, b.d);
    const double delta = rss(pts, joint.n, joint.d) - apart;
    const double allowed = evidence * std::log(static_cast<double>(pts.size())) * sigma * sigma;
    // Parallel neighbours less than the band apart make no corner the border could place.
    const bool step = !meet(a, b) && a.n.dot(b.n) > 0.0 && std::abs(a.d - b.d) < band;
    const double excess = step ? -std::numeric_limits<double>::infinity() : delta - allowed;
    if (excess < best_excess) best = Join{i, joint.n, joint.d}, best_excess = excess;
  }
  return best;
}

}  // namespace

std::vector<OutlineSide> fit_outline_sides(std::vector<OutlineSide> sides, const std::vector<Eigen::Vector2d>& border,
                                           const OutlineFitParameters& p) {
  const double band = p.band_cells * p.cell, end_gap = p.end_cells * p.cell;
  const double min_length = p.min_length_cells * p.cell;
  if (sides.size() < 3) return {};
  std::vector<Eigen::Vector2d> corners(sides.size(), Eigen::Vector2d::Zero());
  for (std::size_t k = 0; k < sides.size(); ++k)
    if (auto m = meet(sides[k], sides[(k + 1) % sides.size()])) corners[k] = *m;
  // Every pass but the last drops or joins a side, so there are fewer passes than sides; the
  // bound only makes that plain.
  for (std::size_t pass = 0, passes = 2 * sides.size() + 4; pass < passes && sides.size() >= 3; ++pass) {
    for (int settle = 0; settle < 3; ++settle) {
      const std::vector<Eigen::Vector2d> moved = corners_of(sides, corners);
      double most = 0.0;
      for (std::size_t k = 0; k < moved.size(); ++k) most = std::max(most, (moved[k] - corners[k]).norm());
      corners = moved;
      // Settled: the corners stood still (a hundredth of a cell) through the last refit.
      if (settle > 0 && most < 0.01 * p.cell) break;
      assign(sides, corners, border, band);
      refit(sides, corners, end_gap);
    }
    corners = corners_of(sides, corners);
    assign(sides, corners, border, band);
    const std::size_t n = sides.size();
    if (n > 3) {
      if (auto k = side_to_drop(sides, corners, min_length)) {
        const std::size_t prev = (*k + n - 1) % n;
        corners[prev] = 0.5 * (corners[prev] + corners[*k]);
        sides.erase(sides.begin() + static_cast<std::ptrdiff_t>(*k));
        corners.erase(corners.begin() + static_cast<std::ptrdiff_t>(*k));
        continue;
      }
      if (auto j = pair_to_join(sides, noise_sigma(sides, 0.1 * p.cell), p.join_evidence, band)) {
        const std::size_t next = (j->at + 1) % n;
        OutlineSide& into = sides[j->at];
        if (sides[next].fixed) into.fixed = true, into.label = sides[next].label;
        into.n = j->n;
        into.d = j->d;
        // Side at+1's far corner becomes the joined side's.
        corners[j->at] = corners[next];
        sides.erase(sides.begin() + static_cast<std::ptrdiff_t>(next));
        corners.erase(corners.begin() + static_cast<std::ptrdiff_t>(next));
        continue;
      }
    }
    break;
  }
  if (sides.size() < 3) return {};
  corners = corners_of(sides, corners);
  assign(sides, corners, border, band);
  for (std::size_t k = 0; k < sides.size(); ++k) sides[k].end = corners[k];
  return sides;
}

}  // namespace cloudshape::pipeline::detail
