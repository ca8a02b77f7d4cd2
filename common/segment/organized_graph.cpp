#include "segment/neighbour_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "segment/detail/graph_moments.hpp"

namespace cloudshape::segment {

using detail::fill_spacing;
using detail::kNodesPerBlock;
using detail::Moments;
using detail::normal_of;

NeighbourGraph build_organized_graph(const PointList& points, const GridLayout& grid,
                                     const config::SegmentConfig& cfg, parallel::ThreadPool* pool) {
  NeighbourGraph g;
  g.viewpoint = Point::Zero();
  const std::size_t width = grid.width;
  const std::size_t height = grid.height;
  std::vector<std::int32_t> image(width * height, -1);
  std::vector<double> point_range(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    image[grid.pixel[i]] = static_cast<std::int32_t>(i);
    point_range[i] = points[i].norm();
  }

  const double target = static_cast<double>(std::max<std::int64_t>(1, cfg.target_nodes));
  const std::size_t stride =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(std::sqrt(points.size() / target))));
  const std::size_t cells_x = (width + stride - 1) / stride;
  const std::size_t cells_y = (height + stride - 1) / stride;
  std::vector<std::uint32_t> cell_node(cells_x * cells_y, kNoNode);
  std::vector<double> range;
  std::vector<std::size_t> node_pixel;

  // A cell's node is its pixel of median range: one flying pixel at a depth edge cannot be it.
  std::vector<std::pair<double, std::int32_t>> cell_pixels;
  for (std::size_t cy = 0; cy < cells_y; ++cy) {
    for (std::size_t cx = 0; cx < cells_x; ++cx) {
      cell_pixels.clear();
      for (std::size_t y = cy * stride; y < std::min(height, (cy + 1) * stride); ++y) {
        for (std::size_t x = cx * stride; x < std::min(width, (cx + 1) * stride); ++x) {
          const std::int32_t i = image[y * width + x];
          if (i >= 0) cell_pixels.emplace_back(point_range[i], i);
        }
      }
      if (cell_pixels.empty()) continue;
      std::nth_element(cell_pixels.begin(), cell_pixels.begin() + cell_pixels.size() / 2, cell_pixels.end());
      const auto& chosen = cell_pixels[cell_pixels.size() / 2];
      cell_node[cy * cells_x + cx] = static_cast<std::uint32_t>(g.nodes.size());
      g.nodes.push_back(points[chosen.second]);
      range.push_back(chosen.first);
      node_pixel.push_back(grid.pixel[chosen.second]);
    }
  }

  const auto same_surface = [&](double ra, double rb) {
    return std::abs(ra - rb) <= cfg.depth_jump * std::min(ra, rb);
  };
  // 8-neighbour cells, in the order a scan that links each cell to its later neighbours gives.
  constexpr int kOrder[8][2] = {{-1, -1}, {0, -1}, {1, -1}, {-1, 0}, {1, 0}, {0, 1}, {1, 1}, {-1, 1}};
  g.adjacency_begin.assign(g.size() + 1, 0);
  g.adjacency.reserve(g.size() * 8);
  for (std::size_t cy = 0; cy < cells_y; ++cy) {
    for (std::size_t cx = 0; cx < cells_x; ++cx) {
      const std::uint32_t a = cell_node[cy * cells_x + cx];
      if (a == kNoNode) continue;
      for (const auto& o : kOrder) {
        const std::ptrdiff_t nx = static_cast<std::ptrdiff_t>(cx) + o[0];
        const std::ptrdiff_t ny = static_cast<std::ptrdiff_t>(cy) + o[1];
        if (nx < 0 || ny < 0 || nx >= static_cast<std::ptrdiff_t>(cells_x) || ny >= static_cast<std::ptrdiff_t>(cells_y)) {
          continue;
        }
        const std::uint32_t b = cell_node[static_cast<std::size_t>(ny) * cells_x + static_cast<std::size_t>(nx)];
        if (b != kNoNode && same_surface(range[a], range[b])) g.adjacency.push_back(b);
      }
      g.adjacency_begin[a + 1] = static_cast<std::uint32_t>(g.adjacency.size());
    }
  }
  fill_spacing(g, 0.0, pool);

  // Every point joins the node of its cell, or of a neighbouring cell, on its side of any jump.
  g.node_of_point.assign(points.size(), kNoNode);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t px = grid.pixel[i] % width;
    const std::size_t py = grid.pixel[i] / width;
    const std::size_t cx = px / stride;
    const std::size_t cy = py / stride;
    const double r = point_range[i];
    const auto node_at = [&](std::ptrdiff_t ox, std::ptrdiff_t oy) {
      const std::ptrdiff_t nx = static_cast<std::ptrdiff_t>(cx) + ox;
      const std::ptrdiff_t ny = static_cast<std::ptrdiff_t>(cy) + oy;
      if (nx < 0 || ny < 0 || nx >= static_cast<std::ptrdiff_t>(cells_x) ||
          ny >= static_cast<std::ptrdiff_t>(cells_y)) {
        return kNoNode;
      }
      const std::uint32_t n = cell_node[static_cast<std::size_t>(ny) * cells_x + static_cast<std::size_t>(nx)];
      return n != kNoNode && same_surface(r, range[n]) ? n : kNoNode;
    };
    std::uint32_t best = node_at(0, 0);
    double best_d = std::numeric_limits<double>::infinity();
    if (best == kNoNode) {
      for (int oy = -1; oy <= 1; ++oy) {
        for (int ox = -1; ox <= 1; ++ox) {
          const std::uint32_t n = node_at(ox, oy);
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
      Moments m;
      m.origin = g.nodes[n];
      const double node_range = range[n];
      const std::ptrdiff_t x_end = std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(width) - 1, px + reach);
      const std::ptrdiff_t y_end = std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(height) - 1, py + reach);
      for (std::ptrdiff_t y = std::max<std::ptrdiff_t>(0, py - reach); y <= y_end; y += step) {
        const std::int32_t* row = image.data() + static_cast<std::size_t>(y) * width;
        for (std::ptrdiff_t x = std::max<std::ptrdiff_t>(0, px - reach); x <= x_end; x += step) {
          const std::int32_t i = row[x];
          if (i >= 0 && same_surface(node_range, point_range[i])) m.add(points[i]);
        }
      }
      normal_of(m, g.normals[n], g.curvature[n]);
      if (g.normals[n].dot(*g.viewpoint - g.nodes[n]) < 0.0) g.normals[n] = -g.normals[n];
    }
  });
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
