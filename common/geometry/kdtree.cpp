#include "geometry/kdtree.hpp"

#include <limits>
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

// nanoflann's RadiusResultSet without the distances: the indices go straight into the caller's
// vector, in the same traversal order, with no pair vector to allocate and copy per query.
class IndexRadiusSet {
 public:
  IndexRadiusSet(double radius, std::vector<std::uint32_t>& out) : radius_(radius), out_(out) { out_.clear(); }
  void init() { out_.clear(); }
  std::size_t size() const { return out_.size(); }
  bool full() const { return true; }
  bool addPoint(double dist, std::uint32_t index) {
    if (dist < radius_) out_.push_back(index);
    return true;
  }
  double worstDist() const { return radius_; }

 private:
  const double radius_;
  std::vector<std::uint32_t>& out_;
};

// Radius search that stops at the first point within the radius.
class AnyRadiusSet {
 public:
  explicit AnyRadiusSet(double radius) : radius_(radius) {}
  void init() { found_ = false; }
  std::size_t size() const { return found_ ? 1 : 0; }
  bool full() const { return true; }
  bool addPoint(double dist, std::uint32_t) {
    found_ = found_ || dist < radius_;
    return !found_;
  }
  double worstDist() const { return radius_; }
  bool found() const { return found_; }

 private:
  const double radius_;
  bool found_ = false;
};

// nanoflann's KNNResultSet for k = 2 holding only its two distances: the same worst distance after
// every point, so the same search and the same second distance.
class TwoNearestSet {
 public:
  std::size_t size() const { return count_; }
  bool full() const { return count_ == 2; }
  bool addPoint(double dist, std::uint32_t) {
    if (dist < first_) {
      second_ = first_;
      first_ = dist;
    } else if (dist < second_) {
      second_ = dist;
    }
    count_ += count_ < 2 ? 1 : 0;
    return true;
  }
  double worstDist() const { return second_; }

 private:
  double first_ = std::numeric_limits<double>::max();
  double second_ = std::numeric_limits<double>::max();
  std::size_t count_ = 0;
};

}  // namespace

struct KdTree::Index {
  explicit Index(const PointList& pts)
      : adaptor{pts}, tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}
  PointListAdaptor adaptor;
  Tree tree;
};

KdTree::KdTree(const PointList& points) : points_(points), index_(std::make_unique<Index>(points)) {}

KdTree::KdTree(PointList&& points)
    : owned_(std::move(points)), points_(owned_), index_(std::make_unique<Index>(owned_)) {}

KdTree::~KdTree() = default;

void KdTree::knn(const Point& query, std::size_t k, std::vector<std::uint32_t>& indices,
                 std::vector<double>* sq_dists) const {
  k = std::min(k, points_.size());
  indices.resize(k);
  // Callers that want no distances still need room for them: one buffer per thread, not one
  // allocation per query.
  thread_local std::vector<double> scratch;
  std::vector<double>& d = sq_dists ? *sq_dists : scratch;
  d.resize(k);
  if (k == 0) return;
  const std::size_t found = index_->tree.knnSearch(query.data(), k, indices.data(), d.data());
  indices.resize(found);
  d.resize(found);
}

double KdTree::nearest_other_sq_dist(std::uint32_t i) const {
  TwoNearestSet found;
  index_->tree.findNeighbors(found, points_[i].data(), nanoflann::SearchParams());
  return found.worstDist();
}

void KdTree::radius(const Point& query, double radius, std::vector<std::uint32_t>& indices) const {
  nanoflann::SearchParams params;
  params.sorted = false;
  IndexRadiusSet found(radius * radius, indices);
  index_->tree.radiusSearchCustomCallback(query.data(), found, params);
}

bool KdTree::any_within(const Point& query, double radius) const {
  nanoflann::SearchParams params;
  params.sorted = false;
  AnyRadiusSet found(radius * radius);
  index_->tree.radiusSearchCustomCallback(query.data(), found, params);
  return found.found();
}

}  // namespace cloudshape::geometry
