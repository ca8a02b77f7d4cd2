#include "pipeline/keypoints.hpp"

#include <algorithm>
#include <optional>

namespace cloudshape::pipeline {

std::uint32_t pursue_vertex(const geometry::KdTree& tree, std::uint32_t start, const Point& centre,
                            std::size_t neighbourhood, std::int64_t max_steps) {
  const PointList& cloud = tree.points();
  std::uint32_t current = start;
  std::vector<std::uint32_t> nb;
  for (std::int64_t step = 0; step < max_steps; ++step) {
    tree.knn(cloud[current], neighbourhood, nb);
    std::uint32_t best = current;
    double best_d = (cloud[current] - centre).squaredNorm();
    for (std::uint32_t j : nb) {
      const double d = (cloud[j] - centre).squaredNorm();
      if (d > best_d) {
        best_d = d;
        best = j;
      }
    }
    if (best == current) break;
    current = best;
  }
  return current;
}

KeypointSet find_keypoints(const PointList& cloud, const PlaneSegmentation& planes,
                           double resolution, const config::KeypointsConfig& cfg,
                           const geometry::KdTree* shared_tree) {
  KeypointSet out;
  if (cloud.empty()) return out;
  out.reference = geometry::minimal_enclosing_sphere(cloud);
  std::optional<geometry::KdTree> own_tree;
  const geometry::KdTree& tree = shared_tree ? *shared_tree : own_tree.emplace(cloud);
  const auto k = static_cast<std::size_t>(std::max<std::int64_t>(3, cfg.neighbourhood));
  std::vector<std::uint32_t> reached;
  std::vector<std::uint32_t> nb;
  for (const PlaneLine& line : planes.lines) {
    for (const Point& extremity : {line.start(), line.end()}) {
      tree.knn(extremity, 1, nb);
      if (nb.empty()) continue;
      reached.push_back(pursue_vertex(tree, nb.front(), out.reference.center, k, cfg.pursuit_max_steps));
    }
  }
  // Several extremities climb to the same vertex (thesis 4.2): keep one key-point per
  // cluster, the one farthest from the centre.
  const Point& c = out.reference.center;
  std::sort(reached.begin(), reached.end(), [&](std::uint32_t a, std::uint32_t b) {
    return (cloud[a] - c).squaredNorm() > (cloud[b] - c).squaredNorm();
  });
  reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
  const double merge = cfg.merge_distance * resolution;
  std::vector<std::uint32_t> kept;
  for (std::uint32_t r : reached) {
    const bool close = std::any_of(kept.begin(), kept.end(), [&](std::uint32_t q) {
      return (cloud[q] - cloud[r]).norm() < merge;
    });
    if (!close) kept.push_back(r);
  }
  for (std::uint32_t r : kept) {
    Keypoint kp;
    kp.index = r;
    tree.knn(cloud[r], k, kp.neighbourhood);
    out.keypoints.push_back(std::move(kp));
  }
  return out;
}

}  // namespace cloudshape::pipeline
