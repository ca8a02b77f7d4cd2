#include "segment/pinhole_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace cloudshape::segment {
namespace {

// A driver writes a pixel's point as ((u - cx) z / fx, (v - cy) z / fy, z): its x / z and y / z
// are the pixel's column and row on two lattices. A tenth of a step holds the rounding of any
// export (six significant digits: about a thousandth of a Kinect's step) and rejects a cloud
// whose directions are not on the lattice (a random direction lies that close with chance 0.2
// per point).
constexpr double kTolerance = 0.1;
constexpr std::size_t kMinPoints = 64;
constexpr std::size_t kMaxSide = 16384;     // pixels along a side: larger is no camera image
constexpr std::size_t kStepSamples = 4096;  // consecutive pairs read for the column step

struct Lattice {
  double origin =
      0.0;  // the coordinate of index 0: the smallest, or the largest for a negative step
  double step = 0.0;
  std::size_t size = 0;  // indices 0 .. size - 1
};

// The lattice spanning [lo, hi] given a rough signed step (within a few per cent: a rounded index
// at the far end is exact), its step refined over the whole span; nothing when the span is no
// multiple of the rough step or too many steps.
std::optional<Lattice> lattice_over(double lo, double hi, double rough) {
  if (!(rough != 0.0) || !(hi >= lo)) return std::nullopt;
  const double steps = (hi - lo) / std::abs(rough);
  if (!(steps < static_cast<double>(kMaxSide))) return std::nullopt;
  const double whole = std::round(steps);
  if (std::abs(steps - whole) > kTolerance) return std::nullopt;
  Lattice l;
  l.origin = rough > 0.0 ? lo : hi;
  l.step = whole > 0.0 ? std::copysign((hi - lo) / whole, rough) : rough;
  l.size = static_cast<std::size_t>(whole) + 1;
  return l;
}

// The index of `value` on `l`, or -1 when it lies more than kTolerance of a step off it.
std::int64_t index_on(const Lattice& l, double value) {
  const double c = (value - l.origin) / l.step;
  const double i = std::round(c);
  return std::abs(c - i) <= kTolerance ? static_cast<std::int64_t>(i) : -1;
}

}  // namespace

std::optional<GridLayout> pinhole_grid(const PointList& points) {
  const std::size_t n = points.size();
  if (n < kMinPoints) return std::nullopt;
  // Directions are divided out again in each pass rather than kept: a non-image cloud costs no
  // memory, and most end in the first pass (a point at or behind the camera's plane).
  const auto a = [&points](std::size_t i) { return points[i].x() / points[i].z(); };
  const auto b = [&points](std::size_t i) { return points[i].y() / points[i].z(); };
  // The camera looks along +z (drivers, ROS optical frames) or -z (a flip for display, as
  // OpenGL's convention has it).
  if (!beyond_camera_plane(points)) return std::nullopt;
  double a_lo = INFINITY, a_hi = -INFINITY, b_lo = INFINITY, b_hi = -INFINITY;
  for (std::size_t i = 0; i < n; ++i) {
    a_lo = std::min(a_lo, a(i));
    a_hi = std::max(a_hi, a(i));
    b_lo = std::min(b_lo, b(i));
    b_hi = std::max(b_hi, b(i));
  }
  // The column step: consecutive points of a row are neighbouring pixels (or a few apart across a
  // hole), rows change once a row, so the median of consecutive differences is one step (negative
  // where the columns run against x / z).
  const std::size_t stride = std::max<std::size_t>(1, (n - 1) / kStepSamples);
  std::vector<double> da;
  da.reserve(kStepSamples + 1);
  for (std::size_t i = 0; i + 1 < n; i += stride) da.push_back(a(i + 1) - a(i));
  std::nth_element(da.begin(), da.begin() + static_cast<std::ptrdiff_t>(da.size() / 2), da.end());
  const double column_step = da[da.size() / 2];
  if (!(column_step != 0.0) || !std::isfinite(column_step)) return std::nullopt;
  // The row step: the smallest change of y / z from one point to the next that is no rounding
  // (more than a quarter of a column step: pixels are about square), one row on, signed as the
  // first such change (rows running the other way too are no raster order: the pixels fail).
  double row_step = 0.0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double d = b(i + 1) - b(i);
    if (!(std::abs(d) > 0.25 * std::abs(column_step))) continue;
    if (row_step == 0.0 ||
        (std::signbit(d) == std::signbit(row_step) && std::abs(d) < std::abs(row_step)))
      row_step = d;
  }
  if (row_step == 0.0) return std::nullopt;  // one row: no image
  const auto columns = lattice_over(a_lo, a_hi, column_step);
  const auto rows = lattice_over(b_lo, b_hi, row_step);
  if (!columns || !rows) return std::nullopt;
  GridLayout grid;
  grid.width = columns->size;
  grid.height = rows->size;
  grid.pixel.resize(n);
  std::int64_t previous = -1;
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t column = index_on(*columns, a(i));
    const std::int64_t row = index_on(*rows, b(i));
    if (column < 0 || row < 0) return std::nullopt;
    const std::int64_t pixel = row * static_cast<std::int64_t>(grid.width) + column;
    if (pixel <= previous) return std::nullopt;
    grid.pixel[i] = static_cast<std::uint32_t>(pixel);
    previous = pixel;
  }
  return grid;
}

bool beyond_camera_plane(const PointList& points) {
  if (points.empty()) return false;
  const bool ahead = points.front().z() > 0.0;
  return std::all_of(points.begin(), points.end(),
                     [ahead](const Point& p) { return ahead ? p.z() > 0.0 : p.z() < 0.0; });
}

}  // namespace cloudshape::segment
