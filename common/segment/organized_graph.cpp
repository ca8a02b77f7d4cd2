// The organized cloud's neighbour graph: one node per pixel cell, edges between neighbouring cells
// on the same surface, normals from each node's window of pixels on its side of every depth jump.
#include "segment/neighbour_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "segment/detail/concave_creases.hpp"
#include "segment/detail/depth_noise.hpp"
#include "segment/detail/graph_moments.hpp"
#include "segment/detail/median_pixel.hpp"

namespace cloudshape::segment {

using detail::fill_spacing;
using detail::kNodesPerBlock;
using detail::normal_of;

namespace {

// The depth noise is read on every this-th row: a median of a quarter of a frame's pixels.
constexpr std::size_t kNoiseRowStep = 4;

// A depth image as the normal windows read it: per pixel its (last) point and that point's range,
// row-major, `width` wide; a pixel without a point has index -1 and a NaN range, which fails
// every same-surface test (an empty pixel is never on a node's surface).
struct PixelImage {
  const std::int32_t* point;
  const double* range;
  std::size_t width;
};

// A node's window: every step-th pixel of every step-th row from (x_begin, y_begin) to (x_end, y_end).
struct Window {
  std::ptrdiff_t x_begin, x_end, y_begin, y_end, step;
};

// Calls f(point index) for each of the window's pixels on the surface at `range`, in row order.
template <class F>
void for_surface_pixels(const PixelImage& image, const Window& w, double range, double depth_jump, F&& f) {
  for (std::ptrdiff_t y = w.y_begin; y <= w.y_end; y += w.step) {
    const double* ranges = image.range + static_cast<std::size_t>(y) * image.width;
    const std::int32_t* points = image.point + static_cast<std::size_t>(y) * image.width;
    for (std::ptrdiff_t x = w.x_begin; x <= w.x_end; x += w.step) {
      if (same_surface(range, ranges[x], depth_jump)) f(static_cast<std::size_t>(points[x]));
    }
  }
}

// Moments::add of the window's points on the surface of the node at `origin` (`range` from the
// sensor), two entries at a time where SSE2 is: each entry the same difference, products and sums
// in the same order (IEEE double lanes), so the same moments. The sums are locals, not an
// object's members, so that they stay in registers across the window.
detail::Moments window_moments(const PointList& points, const PixelImage& image, const Window& w,
                               const Point& origin, double range, double depth_jump) {
  detail::Moments m;
  m.origin = origin;
#if defined(__SSE2__)
  const Point* const point = points.data();
  const __m128d origin_xy = _mm_loadu_pd(origin.data());
  const __m128d origin_z = _mm_load_sd(origin.data() + 2);
  __m128d sum_xy = _mm_setzero_pd(), sum_z = _mm_setzero_pd();
  __m128d xx_xy = _mm_setzero_pd(), xz_yy = _mm_setzero_pd(), yz_zz = _mm_setzero_pd();
  std::size_t count = 0;
  for_surface_pixels(image, w, range, depth_jump, [&](std::size_t i) {
    const __m128d d_xy = _mm_sub_pd(_mm_loadu_pd(point[i].data()), origin_xy);  // (dx, dy)
    const __m128d d_z = _mm_sub_sd(_mm_load_sd(point[i].data() + 2), origin_z);  // (dz, 0)
    sum_xy = _mm_add_pd(sum_xy, d_xy);
    sum_z = _mm_add_sd(sum_z, d_z);
    xx_xy = _mm_add_pd(xx_xy, _mm_mul_pd(d_xy, _mm_unpacklo_pd(d_xy, d_xy)));                     // (dx dx, dy dx)
    xz_yy = _mm_add_pd(xz_yy, _mm_mul_pd(_mm_shuffle_pd(d_z, d_xy, 2), d_xy));                   // (dz dx, dy dy)
    yz_zz = _mm_add_pd(yz_zz, _mm_mul_pd(_mm_unpacklo_pd(d_z, d_z), _mm_shuffle_pd(d_xy, d_z, 1)));  // (dz dy, dz dz)
    ++count;
  });
  alignas(16) double lanes[2];
  _mm_store_pd(lanes, sum_xy);
  m.sum = {lanes[0], lanes[1], _mm_cvtsd_f64(sum_z)};
  _mm_store_pd(lanes, xx_xy);
  m.xx = lanes[0];
  m.xy = lanes[1];
  _mm_store_pd(lanes, xz_yy);
  m.xz = lanes[0];
  m.yy = lanes[1];
  _mm_store_pd(lanes, yz_zz);
  m.yz = lanes[0];
  m.zz = lanes[1];
  m.count = count;
#else
  for_surface_pixels(image, w, range, depth_jump, [&](std::size_t i) { m.add(points[i]); });
#endif
  return m;
}

}  // namespace

NeighbourGraph build_organized_graph(const PointList& points, const GridLayout& grid,
                                     const config::SegmentConfig& cfg, parallel::ThreadPool* pool) {
  NeighbourGraph g;
  g.viewpoint = Point::Zero();
  const std::size_t width = grid.width;
  const std::size_t height = grid.height;
  // Per pixel its (last) point and that point's range, apart: the windows test contiguous ranges
  // and load a point only when it is on the node's surface (see PixelImage).
  std::vector<std::int32_t> image(width * height, -1);
  std::vector<double> pixel_range(width * height, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < points.size(); ++i) {
    image[grid.pixel[i]] = static_cast<std::int32_t>(i);
    pixel_range[grid.pixel[i]] = points[i].norm();
  }

  const double target = static_cast<double>(std::max<std::int64_t>(1, cfg.target_nodes));
  const std::size_t stride =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(std::sqrt(points.size() / target))));
  const std::size_t cells_x = (width + stride - 1) / stride;
  const std::size_t cells_y = (height + stride - 1) / stride;
  // Cells with a border of empty ones around them, two normal radii wide for the creases (at
  // most as wide as the cells reach): a neighbour look-up needs no bounds test.
  const auto radius = static_cast<std::size_t>(std::max<std::int64_t>(1, cfg.normal_radius));
  const std::size_t extent = std::max(cells_x, cells_y);
  const std::size_t border = radius <= extent / 2 ? 2 * radius : extent;
  const std::size_t padded_x = cells_x + 2 * border;
  const auto cell_at = [&](std::size_t cx, std::size_t cy) { return (cy + border) * padded_x + cx + border; };
  std::vector<std::uint32_t> cell_node(padded_x * (cells_y + 2 * border), kNoNode);
  std::vector<double> range;
  std::vector<std::size_t> node_pixel, node_cell;

  // A cell's node is its pixel of median range: one flying pixel at a depth edge cannot be it.
  std::vector<double> cell_ranges(stride * stride);
  std::vector<std::int32_t> cell_points(stride * stride);
  std::vector<std::pair<double, std::int32_t>> scratch;
  for (std::size_t cy = 0; cy < cells_y; ++cy) {
    const std::size_t y_end = std::min(height, (cy + 1) * stride);
    for (std::size_t cx = 0; cx < cells_x; ++cx) {
      const std::size_t x_end = std::min(width, (cx + 1) * stride);
      std::size_t count = 0;
      for (std::size_t y = cy * stride; y < y_end; ++y) {
        for (std::size_t x = cx * stride; x < x_end; ++x) {
          const std::int32_t i = image[y * width + x];
          if (i < 0) continue;
          cell_ranges[count] = pixel_range[y * width + x];
          cell_points[count++] = i;
        }
      }
      if (count == 0) continue;
      const std::size_t chosen = detail::median_slot(cell_ranges.data(), cell_points.data(), count, scratch);
      cell_node[cell_at(cx, cy)] = static_cast<std::uint32_t>(g.nodes.size());
      node_cell.push_back(cell_at(cx, cy));
      g.nodes.push_back(points[cell_points[chosen]]);
      range.push_back(cell_ranges[chosen]);
      node_pixel.push_back(grid.pixel[cell_points[chosen]]);
    }
  }

  const auto same_surface = [&](double ra, double rb) { return segment::same_surface(ra, rb, cfg.depth_jump); };
  // 8-neighbour cells, in the order a scan that links each cell to its later neighbours gives.
  constexpr int kOrder[8][2] = {{-1, -1}, {0, -1}, {1, -1}, {-1, 0}, {1, 0}, {0, 1}, {1, 1}, {-1, 1}};
  std::ptrdiff_t offsets[8];
  for (int k = 0; k < 8; ++k) offsets[k] = kOrder[k][1] * static_cast<std::ptrdiff_t>(padded_x) + kOrder[k][0];
  g.adjacency_begin.assign(g.size() + 1, 0);
  g.adjacency.reserve(g.size() * 8);
  for (std::size_t cy = 0; cy < cells_y; ++cy) {
    for (std::size_t cx = 0; cx < cells_x; ++cx) {
      const std::uint32_t* cell = cell_node.data() + cell_at(cx, cy);
      const std::uint32_t a = *cell;
      if (a == kNoNode) continue;
      for (const std::ptrdiff_t o : offsets) {
        const std::uint32_t b = cell[o];
        if (b != kNoNode && same_surface(range[a], range[b])) g.adjacency.push_back(b);
      }
      g.adjacency_begin[a + 1] = static_cast<std::uint32_t>(g.adjacency.size());
    }
  }
  fill_spacing(g, 0.0, pool);

  // Every point joins the node of its cell, or of a neighbouring cell, on its side of any jump.
  g.node_of_point.assign(points.size(), kNoNode);
  // Per pixel column its cell's column: no division per point.
  std::vector<std::size_t> cell_column(width);
  for (std::size_t x = 0; x < width; ++x) cell_column[x] = x / stride;
  std::size_t row_begin = 0, row_end = width;  // the pixel row of the point before
  const std::uint32_t* row_cells = cell_node.data() + cell_at(0, 0);  // its first cell
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (grid.pixel[i] < row_begin || grid.pixel[i] >= row_end) {
      const std::size_t row = grid.pixel[i] / width;
      row_begin = row * width;
      row_end = row_begin + width;
      row_cells = cell_node.data() + cell_at(0, row / stride);
    }
    const std::uint32_t* cell = row_cells + cell_column[grid.pixel[i] - row_begin];
    // (A pixel holds its last point: an earlier one at the same pixel has its own range.)
    const double r = image[grid.pixel[i]] == static_cast<std::int32_t>(i) ? pixel_range[grid.pixel[i]] : points[i].norm();
    const auto node_at = [&](std::ptrdiff_t offset) {
      const std::uint32_t n = cell[offset];
      return n != kNoNode && same_surface(r, range[n]) ? n : kNoNode;
    };
    std::uint32_t best = node_at(0);
    double best_d = std::numeric_limits<double>::infinity();
    if (best == kNoNode) {
      for (std::ptrdiff_t oy = -1; oy <= 1; ++oy) {
        for (std::ptrdiff_t ox = -1; ox <= 1; ++ox) {
          const std::uint32_t n = node_at(oy * static_cast<std::ptrdiff_t>(padded_x) + ox);
          if (n == kNoNode) continue;
          const double d = (points[i] - g.nodes[n]).squaredNorm();
          if (d < best_d) {
            best = n;
            best_d = d;
          }
        }
      }
    }
    g.node_of_point[i] = best;
  }

  // Normals from the pixels around each node that lie on its side of every depth jump. One pixel
  // per cell is enough for a covariance, and keeps the cost per node fixed; where each pixel's
  // depth is noisy on its own, the samples spread further, so that the noise tilts a normal by
  // at most half the angle that parts smooth patches (one deviation along either axis): a table
  // whose normals scatter beyond it is no plane to the structure search.
  const double noise = detail::depth_noise_ratio({points, image, pixel_range, width, height},
                                                 cfg.depth_jump, kNoiseRowStep);
  // The step the noise alone asks for (from single pixels): beyond one, the pixels are noisy.
  const std::size_t noise_step = detail::normal_window_step(
      noise, 1, cfg.normal_radius, 0.5 * cfg.smooth_degrees, std::max(width, height));
  g.noisy_pixels = noise_step > 1;
  const std::size_t window_step = std::max(stride, noise_step);
  const std::ptrdiff_t reach =
      static_cast<std::ptrdiff_t>(std::max<std::int64_t>(1, cfg.normal_radius) * window_step);
  const std::ptrdiff_t step = static_cast<std::ptrdiff_t>(window_step);
  const PixelImage image_view{image.data(), pixel_range.data(), width};
  g.normals.resize(g.size());
  g.curvature.resize(g.size());
  parallel::for_blocks(pool, g.size(), kNodesPerBlock, [&](std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n) {
      const std::ptrdiff_t px = static_cast<std::ptrdiff_t>(node_pixel[n] % width);
      const std::ptrdiff_t py = static_cast<std::ptrdiff_t>(node_pixel[n] / width);
      const Window w{std::max<std::ptrdiff_t>(0, px - reach),
                     std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(width) - 1, px + reach),
                     std::max<std::ptrdiff_t>(0, py - reach),
                     std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(height) - 1, py + reach), step};
      normal_of(window_moments(points, image_view, w, g.nodes[n], range[n], cfg.depth_jump), g.normals[n],
                g.curvature[n]);
      if (g.normals[n].dot(*g.viewpoint - g.nodes[n]) < 0.0) g.normals[n] = -g.normals[n];
    }
  });

  const detail::CellLayout cells{padded_x, border, std::move(cell_node), std::move(node_cell), std::move(range)};
  g.crease = detail::concave_creases(g, cells, cfg, pool);
  return g;
}

void orient_to_viewpoint(NeighbourGraph& g, const std::optional<Point>& viewpoint) {
  g.viewpoint = viewpoint;
  if (!g.viewpoint) return;
  for (std::size_t n = 0; n < g.size(); ++n) {
    if (g.normals[n].dot(*g.viewpoint - g.nodes[n]) < 0.0) g.normals[n] = -g.normals[n];
  }
}

}  // namespace cloudshape::segment
