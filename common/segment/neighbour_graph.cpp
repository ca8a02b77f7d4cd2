#include "segment/neighbour_graph.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "geometry/detail/flat_hash.hpp"
#include "geometry/grid_neighbours.hpp"
#include "geometry/pca.hpp"
#include "geometry/voxel_grid.hpp"
#include "segment/line_neighbourhoods.hpp"

namespace cloudshape::segment {
namespace {

// A voxel key packs 21 bits per axis: an axis holds at most this many cells, with room to spare.
constexpr double kMaxCellsPerAxis = 1 << 20;
// Nodes per block of the parallel normal loops: a few thousand blocks' overhead at most.
constexpr std::size_t kNodesPerBlock = 512;

// Running first and second moments of a point set, for a normal without storing the points.
// The second moments are symmetric: six sums, each the same products in the same order as the
// full outer product's entry (the same covariance to the bit, two thirds of the work).
struct Moments {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // subtracted first: keeps float64 sums exact enough far from 0
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double xx = 0.0, xy = 0.0, xz = 0.0, yy = 0.0, yz = 0.0, zz = 0.0;
  std::size_t count = 0;

  void add(const Point& p) {
    const Eigen::Vector3d d = p - origin;
    sum += d;
    xx += d.x() * d.x();
    xy += d.y() * d.x();
    xz += d.z() * d.x();
    yy += d.y() * d.y();
    yz += d.z() * d.y();
    zz += d.z() * d.z();
    ++count;
  }
  // At least one point added.
  Eigen::Matrix3d covariance() const {
    Eigen::Matrix3d outer;
    outer << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    const Eigen::Vector3d mean = sum / static_cast<double>(count);
    return outer / static_cast<double>(count) - mean * mean.transpose();
  }
};

// Normal (smallest principal direction) and surface variation; a default up normal when the
// neighbourhood is too small to say. `spread`, if given: second over first standard deviation.
void normal_of(const Moments& m, Eigen::Vector3d& normal, double& curvature, double* spread = nullptr) {
  if (spread) *spread = 1.0;
  if (m.count < 3) {
    normal = Eigen::Vector3d::UnitZ();
    curvature = 1.0 / 3.0;
    return;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(m.covariance());
  normal = eig.eigenvectors().col(0).normalized();
  const double total = eig.eigenvalues().sum();
  curvature = total > 0.0 ? std::max(0.0, eig.eigenvalues()(0)) / total : 0.0;
  if (spread) {
    const double major = eig.eigenvalues()(2);
    *spread = major > 0.0 ? std::sqrt(std::max(0.0, eig.eigenvalues()(1)) / major) : 0.0;
  }
}

// Whether a neighbourhood of three points or more spreads less than `line` across its length
// (normal_of's spread, from the eigenvalues alone: the direct solver computes them the same way
// with or without eigenvectors), and then its direction (the largest principal one, unit).
bool along_a_line(const Moments& m, double line, Eigen::Vector3d& direction) {
  if (m.count < 3) return false;
  const Eigen::Matrix3d cov = m.covariance();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(cov, Eigen::EigenvaluesOnly);
  const double major = eig.eigenvalues()(2);
  const double spread = major > 0.0 ? std::sqrt(std::max(0.0, eig.eigenvalues()(1)) / major) : 0.0;
  if (spread >= line) return false;
  eig.computeDirect(cov);
  direction = eig.eigenvectors().col(2).normalized();
  return true;
}

// The CSR adjacency with the extra (symmetric) edges added, each neighbour listed once.
void add_edges(NeighbourGraph& g, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges) {
  if (edges.empty()) return;
  std::vector<std::vector<std::uint32_t>> extra(g.size());
  for (const auto& [a, b] : edges) {
    extra[a].push_back(b);
    extra[b].push_back(a);
  }
  std::vector<std::uint32_t> begin(g.size() + 1, 0), adjacency;
  adjacency.reserve(g.adjacency.size() + 2 * edges.size());
  std::vector<std::uint32_t> near;
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    near.assign(g.adjacency.begin() + g.adjacency_begin[n], g.adjacency.begin() + g.adjacency_begin[n + 1]);
    near.insert(near.end(), extra[n].begin(), extra[n].end());
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    adjacency.insert(adjacency.end(), near.begin(), near.end());
    begin[n + 1] = static_cast<std::uint32_t>(adjacency.size());
  }
  g.adjacency_begin.swap(begin);
  g.adjacency.swap(adjacency);
}

void fill_spacing(NeighbourGraph& g, double fallback, parallel::ThreadPool* pool) {
  g.spacing.assign(g.size(), fallback);
  parallel::for_blocks(pool, g.size(), kNodesPerBlock, [&](std::size_t begin, std::size_t end) {
    for (auto n = static_cast<std::uint32_t>(begin); n < end; ++n) {
      double sum = 0.0;
      int count = 0;
      g.for_neighbours(n, [&](std::uint32_t m) {
        sum += (g.nodes[n] - g.nodes[m]).norm();
        ++count;
      });
      if (count > 0) g.spacing[n] = sum / count;
    }
  });
}

}  // namespace

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

namespace {

// finest_voxel of points within `box`.
double finest_in(const PointList& points, const geometry::Bounds& box, parallel::ThreadPool* pool) {
  // Three times the sampling: 26-neighbour voxels must connect a surface's points where its
  // sampling thins out. The extent bounds a cell index without squares, which underflow for a
  // cloud of 1e-253 (found by fuzzing).
  return std::max(3.0 * geometry::mean_nearest_neighbour_distance(points, 4000, pool),
                  (box.max - box.min).maxCoeff() / kMaxCellsPerAxis);
}

}  // namespace

double finest_voxel(const PointList& points, parallel::ThreadPool* pool) {
  return points.empty() ? 0.0 : finest_in(points, geometry::bounding_box(points), pool);
}

double budget_voxel(const PointList& points, const config::SegmentConfig& cfg, parallel::ThreadPool* pool) {
  if (points.empty()) return 0.0;
  const double target = static_cast<double>(std::max<std::int64_t>(1, cfg.target_nodes));
  const geometry::Bounds box = geometry::bounding_box(points);
  return std::max(box.diagonal() / std::sqrt(target), finest_in(points, box, pool));
}

NeighbourGraph build_voxel_graph(const PointList& points, const config::SegmentConfig& cfg,
                                 parallel::ThreadPool* pool) {
  return build_voxel_graph(points, budget_voxel(points, cfg, pool), cfg.target_nodes, cfg, pool);
}

NeighbourGraph build_voxel_graph(const PointList& points, double voxel, std::optional<std::int64_t> max_nodes,
                                 const config::SegmentConfig& cfg, parallel::ThreadPool* pool) {
  NeighbourGraph g;
  g.node_of_point.assign(points.size(), kNoNode);
  if (points.empty()) {
    g.adjacency_begin.assign(1, 0);
    return g;
  }
  const geometry::Bounds box = geometry::bounding_box(points);
  const Point origin = box.min;
  // A budget of nodes caps the voxel count (1.3 times it); none: every voxel the points fill (a
  // voxel never finer than finest_voxel fills no more than there are points).
  const double target = static_cast<double>(std::max<std::int64_t>(1, max_nodes.value_or(0)));
  const double cap = max_nodes ? 1.3 * target : static_cast<double>(points.size());
  voxel = std::max(voxel, 1e-300);

  using Key = std::uint64_t;
  const auto key_of = [&](const Point& p, double v) {
    const Eigen::Vector3d c = ((p - origin) / v).array().floor();
    return (static_cast<Key>(c.x()) << 42) | (static_cast<Key>(c.y()) << 21) | static_cast<Key>(c.z());
  };
  // Node ids in order of first appearance; each point's node kept from the pass that found them.
  std::vector<Key> keys;
  std::vector<std::uint32_t> node;
  const auto bin = [&](double v) {
    geometry::detail::CellMap voxels(std::min<std::size_t>(points.size(), static_cast<std::size_t>(cap) + 1));
    keys.clear();
    node.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Key key = key_of(points[i], v);
      bool inserted = false;
      node[i] = voxels.find_or_insert(key, static_cast<std::uint32_t>(keys.size()), inserted);
      if (inserted) {
        keys.push_back(key);
        if (static_cast<double>(keys.size()) > cap) return voxels;
      }
    }
    return voxels;
  };
  // Grow the voxel until the node budget holds; a surface fills voxels with the square of the edge.
  geometry::detail::CellMap voxels = bin(voxel);
  for (int attempt = 1; attempt < 40 && static_cast<double>(keys.size()) > cap; ++attempt) {
    voxel *= 1.25;
    voxels = bin(voxel);
  }
  const std::size_t nodes = keys.size();
  g.nodes.assign(nodes, Point::Zero());
  std::vector<std::size_t> counts(nodes, 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::uint32_t n = node[i];
    g.node_of_point[i] = n;
    g.nodes[n] += points[i];
    ++counts[n];
  }
  for (std::size_t n = 0; n < g.size(); ++n) g.nodes[n] /= static_cast<double>(counts[n]);

  // Adjacency is symmetric: each voxel looks up only the 13 neighbours after it (in key order),
  // and each pair found is listed on both sides; rows are then sorted by node id.
  // Blocks of nodes find their pairs on the pool; the pairs are joined in block order.
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> pairs_of_block((nodes + kNodesPerBlock - 1) / kNodesPerBlock);
  parallel::for_blocks(pool, nodes, kNodesPerBlock, [&](std::size_t begin, std::size_t end) {
    auto& found = pairs_of_block[begin / kNodesPerBlock];
    found.reserve((end - begin) * 6);
    for (std::size_t n = begin; n < end; ++n) {
      const Key key = keys[n];
      const std::int64_t x = static_cast<std::int64_t>(key >> 42);
      const std::int64_t y = static_cast<std::int64_t>((key >> 21) & 0x1FFFFF);
      const std::int64_t z = static_cast<std::int64_t>(key & 0x1FFFFF);
      for (int dx = 0; dx <= 1; ++dx) {
        for (int dy = dx == 0 ? 0 : -1; dy <= 1; ++dy) {
          for (int dz = dx == 0 && dy == 0 ? 1 : -1; dz <= 1; ++dz) {
            if (y + dy < 0 || z + dz < 0) continue;
            const Key k = (static_cast<Key>(x + dx) << 42) | (static_cast<Key>(y + dy) << 21) | static_cast<Key>(z + dz);
            const std::uint32_t m = voxels.find(k);
            if (m != geometry::detail::CellMap::kAbsent) found.emplace_back(static_cast<std::uint32_t>(n), m);
          }
        }
      }
    }
  });
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const auto& found : pairs_of_block) pairs.insert(pairs.end(), found.begin(), found.end());
  g.adjacency_begin.assign(nodes + 1, 0);
  for (const auto& [a, b] : pairs) {
    ++g.adjacency_begin[a + 1];
    ++g.adjacency_begin[b + 1];
  }
  for (std::size_t n = 0; n < nodes; ++n) g.adjacency_begin[n + 1] += g.adjacency_begin[n];
  g.adjacency.resize(2 * pairs.size());
  {
    std::vector<std::uint32_t> next(g.adjacency_begin.begin(), g.adjacency_begin.end() - 1);
    for (const auto& [a, b] : pairs) {
      g.adjacency[next[a]++] = b;
      g.adjacency[next[b]++] = a;
    }
  }
  parallel::for_blocks(pool, nodes, kNodesPerBlock, [&](std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n) {
      std::sort(g.adjacency.begin() + g.adjacency_begin[n], g.adjacency.begin() + g.adjacency_begin[n + 1]);
    }
  });
  fill_spacing(g, voxel, pool);

  const std::size_t k = std::min<std::size_t>(g.size(), static_cast<std::size_t>(std::max<std::int64_t>(3, cfg.normal_neighbours)));
  // Nodes sit about a voxel apart on a surface: the k-th lies within sqrt(k / pi) voxels. A grid
  // cell of 0.6 sqrt(k) voxels costs the fewest distances plus wider searches on both thin
  // (noise-free) and thick (noisy) surfaces (callgrind, 100k-point boxes: 0.75 cost 1.2-1.4x
  // more, 0.5 0.8x on the noisy one but 2x on the thin one).
  std::vector<std::uint32_t> knn;
  geometry::all_nearest_neighbours(g.nodes, k, 0.6 * std::sqrt(static_cast<double>(k)) * voxel, knn, pool);
  g.normals.resize(g.size());
  g.curvature.resize(g.size());
  std::vector<char> linear(g.size(), 0);
  parallel::for_blocks(pool, g.size(), kNodesPerBlock, [&](std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n) {
      Moments m;
      m.origin = g.nodes[n];
      for (std::size_t j = 0; j < k; ++j) m.add(g.nodes[knn[n * k + j]]);
      double spread = 1.0;
      normal_of(m, g.normals[n], g.curvature[n], &spread);
      linear[n] = m.count >= 3 && spread < cfg.line_spread ? 1 : 0;
    }
  });
  // A node whose voxel neighbours lie on a line through it (one on each side at least: a pair of
  // stray points is no ring) sits on one scan ring.
  std::vector<Eigen::Vector3d> line_of(g.size(), Eigen::Vector3d::Zero());
  // The eigenvalues alone tell the spread; the eigenvectors are computed only for the few on a line.
  parallel::for_blocks(pool, g.size(), kNodesPerBlock, [&](std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n) {
      Moments m;
      m.origin = g.nodes[n];
      m.add(g.nodes[n]);
      g.for_neighbours(static_cast<std::uint32_t>(n), [&](std::uint32_t j) { m.add(g.nodes[j]); });
      if (!along_a_line(m, cfg.line_spread, line_of[n])) continue;
      if (!line_of[n].allFinite()) line_of[n].setZero();
    }
  });
  // The spacing stays that of the voxel neighbours (along a ring): the extra edges only join
  // rings into one surface.
  add_edges(g, widen_line_neighbourhoods(g.nodes, linear, line_of, cfg, g.normals, g.curvature));
  return g;
}

}  // namespace cloudshape::segment
