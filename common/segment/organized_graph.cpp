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
#include "segment/detail/graph_moments.hpp"

namespace cloudshape::segment {

using detail::fill_spacing;
using detail::kNodesPerBlock;
using detail::normal_of;

namespace {

// A pixel's point and range, side by side for the windows' reads; a pixel without a point has a
// NaN range, which fails every same-surface test (an empty pixel is never on a node's surface).
struct Pixel {
  Point point = Point::Zero();
  double range = std::numeric_limits<double>::quiet_NaN();
};

// Moments::add over a node's window, two entries at a time where SSE2 is: each entry the same
// difference, products and sums in the same order (IEEE double lanes), so the same moments.
class WindowMoments {
 public:
  explicit WindowMoments(const Point& origin) {
    m_.origin = origin;
#if defined(__SSE2__)
    origin_xy_ = _mm_loadu_pd(origin.data());
    origin_z_ = _mm_load_sd(origin.data() + 2);
#endif
  }
  void add(const Point& p) {
#if defined(__SSE2__)
    const __m128d d_xy = _mm_sub_pd(_mm_loadu_pd(p.data()), origin_xy_);  // (dx, dy)
    const __m128d d_z = _mm_sub_sd(_mm_load_sd(p.data() + 2), origin_z_);  // (dz, 0)
    sum_xy_ = _mm_add_pd(sum_xy_, d_xy);
    sum_z_ = _mm_add_sd(sum_z_, d_z);
    xx_xy_ = _mm_add_pd(xx_xy_, _mm_mul_pd(d_xy, _mm_unpacklo_pd(d_xy, d_xy)));            // (dx dx, dy dx)
    xz_yy_ = _mm_add_pd(xz_yy_, _mm_mul_pd(_mm_shuffle_pd(d_z, d_xy, 2), d_xy));          // (dz dx, dy dy)
    yz_zz_ = _mm_add_pd(yz_zz_, _mm_mul_pd(_mm_unpacklo_pd(d_z, d_z), _mm_shuffle_pd(d_xy, d_z, 1)));  // (dz dy, dz dz)
    ++m_.count;
#else
    m_.add(p);
#endif
  }
  const detail::Moments& moments() {
#if defined(__SSE2__)
    alignas(16) double lanes[2];
    _mm_store_pd(lanes, sum_xy_);
    m_.sum = {lanes[0], lanes[1], _mm_cvtsd_f64(sum_z_)};
    _mm_store_pd(lanes, xx_xy_);
    m_.xx = lanes[0];
    m_.xy = lanes[1];
    _mm_store_pd(lanes, xz_yy_);
    m_.xz = lanes[0];
    m_.yy = lanes[1];
    _mm_store_pd(lanes, yz_zz_);
    m_.yz = lanes[0];
    m_.zz = lanes[1];
#endif
    return m_;
  }

 private:
  detail::Moments m_;
#if defined(__SSE2__)
  __m128d origin_xy_, origin_z_;
  __m128d sum_xy_ = _mm_setzero_pd(), sum_z_ = _mm_setzero_pd();
  __m128d xx_xy_ = _mm_setzero_pd(), xz_yy_ = _mm_setzero_pd(), yz_zz_ = _mm_setzero_pd();
#endif
};

}  // namespace

NeighbourGraph build_organized_graph(const PointList& points, const GridLayout& grid,
                                     const config::SegmentConfig& cfg, parallel::ThreadPool* pool) {
  NeighbourGraph g;
  g.viewpoint = Point::Zero();
  const std::size_t width = grid.width;
  const std::size_t height = grid.height;
  std::vector<std::int32_t> image(width * height, -1);
  std::vector<Pixel> pixels(width * height);
  for (std::size_t i = 0; i < points.size(); ++i) {
    image[grid.pixel[i]] = static_cast<std::int32_t>(i);
    pixels[grid.pixel[i]] = {points[i], points[i].norm()};
  }

  const double target = static_cast<double>(std::max<std::int64_t>(1, cfg.target_nodes));
  const std::size_t stride =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(std::sqrt(points.size() / target))));
  const std::size_t cells_x = (width + stride - 1) / stride;
  const std::size_t cells_y = (height + stride - 1) / stride;
  // Cells with a border of empty ones around them: a neighbour look-up needs no bounds test.
  const std::size_t padded_x = cells_x + 2;
  const auto cell_at = [&](std::size_t cx, std::size_t cy) { return (cy + 1) * padded_x + cx + 1; };
  std::vector<std::uint32_t> cell_node(padded_x * (cells_y + 2), kNoNode);
  std::vector<double> range;
  std::vector<std::size_t> node_pixel;

  // A cell's node is its pixel of median range: one flying pixel at a depth edge cannot be it.
  std::vector<std::pair<double, std::int32_t>> cell_pixels;
  for (std::size_t cy = 0; cy < cells_y; ++cy) {
    const std::size_t y_end = std::min(height, (cy + 1) * stride);
    for (std::size_t cx = 0; cx < cells_x; ++cx) {
      const std::size_t x_end = std::min(width, (cx + 1) * stride);
      cell_pixels.clear();
      for (std::size_t y = cy * stride; y < y_end; ++y) {
        for (std::size_t x = cx * stride; x < x_end; ++x) {
          const std::int32_t i = image[y * width + x];
          if (i >= 0) cell_pixels.emplace_back(pixels[y * width + x].range, i);
        }
      }
      if (cell_pixels.empty()) continue;
      std::nth_element(cell_pixels.begin(), cell_pixels.begin() + cell_pixels.size() / 2, cell_pixels.end());
      const auto& chosen = cell_pixels[cell_pixels.size() / 2];
      cell_node[cell_at(cx, cy)] = static_cast<std::uint32_t>(g.nodes.size());
      g.nodes.push_back(points[chosen.second]);
      range.push_back(chosen.first);
      node_pixel.push_back(grid.pixel[chosen.second]);
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
  std::size_t row = 0, row_begin = 0, row_end = width;  // the pixel row of the point before
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (grid.pixel[i] < row_begin || grid.pixel[i] >= row_end) {
      row = grid.pixel[i] / width;
      row_begin = row * width;
      row_end = row_begin + width;
    }
    const std::uint32_t* cell = cell_node.data() + cell_at((grid.pixel[i] - row_begin) / stride, row / stride);
    // (A pixel holds its last point: an earlier one at the same pixel has its own range.)
    const double r = image[grid.pixel[i]] == static_cast<std::int32_t>(i) ? pixels[grid.pixel[i]].range : points[i].norm();
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

  // Normals from the pixels around each node that lie on its side of every depth jump.
  const std::ptrdiff_t reach = static_cast<std::ptrdiff_t>(std::max<std::int64_t>(1, cfg.normal_radius) * stride);
  // One pixel per cell is enough for a covariance, and keeps the cost per node fixed.
  const std::ptrdiff_t step = static_cast<std::ptrdiff_t>(stride);
  g.normals.resize(g.size());
  g.curvature.resize(g.size());
  parallel::for_blocks(pool, g.size(), kNodesPerBlock, [&](std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n) {
      const std::ptrdiff_t px = static_cast<std::ptrdiff_t>(node_pixel[n] % width);
      const std::ptrdiff_t py = static_cast<std::ptrdiff_t>(node_pixel[n] / width);
      WindowMoments m(g.nodes[n]);
      const double node_range = range[n];
      const std::ptrdiff_t x_end = std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(width) - 1, px + reach);
      const std::ptrdiff_t y_end = std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(height) - 1, py + reach);
      const std::ptrdiff_t x_begin = std::max<std::ptrdiff_t>(0, px - reach);
      for (std::ptrdiff_t y = std::max<std::ptrdiff_t>(0, py - reach); y <= y_end; y += step) {
        const Pixel* line = pixels.data() + static_cast<std::size_t>(y) * width;
        for (std::ptrdiff_t x = x_begin; x <= x_end; x += step) {
          if (same_surface(node_range, line[x].range)) m.add(line[x].point);
        }
      }
      normal_of(m.moments(), g.normals[n], g.curvature[n]);
      if (g.normals[n].dot(*g.viewpoint - g.nodes[n]) < 0.0) g.normals[n] = -g.normals[n];
    }
  });

  detail::CellLayout cells{cells_x, cells_y, std::vector<std::uint32_t>(cells_x * cells_y), {}, std::move(range)};
  for (std::size_t cy = 0; cy < cells_y; ++cy) {
    for (std::size_t cx = 0; cx < cells_x; ++cx) cells.node_of_cell[cy * cells_x + cx] = cell_node[cell_at(cx, cy)];
  }
  cells.cell_of_node.resize(g.size());
  for (std::size_t n = 0; n < g.size(); ++n) cells.cell_of_node[n] = {node_pixel[n] % width / stride, node_pixel[n] / width / stride};
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
