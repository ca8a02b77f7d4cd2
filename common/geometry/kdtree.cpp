#include "geometry/kdtree.hpp"

#include <nanoflann.hpp>

namespace cloudshape::geometry {
namespace {

struct PointListAdaptor {
  const PointList& pts;
  std::size_t kdtree_get_point_count() const { return pts.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return pts[i][dim]; }
  template <class BBox>
  bool kdtree_get_bbox(BBox&) const {
    return false;
  }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<
    nanoflann::L2_Simple_Adaptor<double, PointListAdaptor>, PointListAdaptor, 3, std::uint32_t>;

}  // namespace

struct KdTree::Index {
  explicit Index(const PointList& pts)
      : adaptor{pts}, tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}
  PointListAdaptor adaptor;
  Tree tree;
};

KdTree::KdTree(const PointList& points) : points_(points), index_(std::make_unique<Index>(points)) {}

KdTree::~KdTree() = default;

void KdTree::knn(const Point& query, std::size_t k, std::vector<std::uint32_t>& indices,
                 std::vector<double>* sq_dists) const {
  k = std::min(k, points_.size());
  indices.resize(k);
  std::vector<double> local;
  std::vector<double>& d = sq_dists ? *sq_dists : local;
  d.resize(k);
  if (k == 0) return;
  const std::size_t found = index_->tree.knnSearch(query.data(), k, indices.data(), d.data());
  indices.resize(found);
  d.resize(found);
}

void KdTree::radius(const Point& query, double radius, std::vector<std::uint32_t>& indices) const {
  std::vector<std::pair<std::uint32_t, double>> matches;
  nanoflann::SearchParams params;
  params.sorted = false;
  index_->tree.radiusSearch(query.data(), radius * radius, matches, params);
  indices.clear();
  indices.reserve(matches.size());
  for (const auto& m : matches) indices.push_back(m.first);
}

}  // namespace cloudshape::geometry
