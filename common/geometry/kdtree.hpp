// k-nearest-neighbour and radius queries over a PointList, through nanoflann.
// The tree keeps a reference to the points (they must outlive it unchanged) or owns them.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/point_cloud.hpp"

namespace cloudshape::geometry {

class KdTree {
 public:
  explicit KdTree(const PointList& points);
  // Owns the points: a tree that travels with an object's cloud (shared by its stages).
  explicit KdTree(PointList&& points);
  ~KdTree();
  KdTree(const KdTree&) = delete;
  KdTree& operator=(const KdTree&) = delete;

  // Indices of the k nearest points to `query` (the query point itself included when
  // it is in the cloud), nearest first; squared distances in `sq_dists` if given.
  void knn(const Point& query, std::size_t k, std::vector<std::uint32_t>& indices,
           std::vector<double>* sq_dists = nullptr) const;

  // The squared distance from points()[i] to its nearest other point (0 beside a duplicate; the
  // tree holds two points or more): the second distance knn(points()[i], 2) gives, by the same
  // search, without its vectors.
  double nearest_other_sq_dist(std::uint32_t i) const;

  // Indices of all points within `radius` of `query`, in no particular order.
  void radius(const Point& query, double radius, std::vector<std::uint32_t>& indices) const;

  // Whether any point lies within `radius` of `query` (the same test as radius(): stops at the first).
  bool any_within(const Point& query, double radius) const;

  const PointList& points() const { return points_; }

 private:
  struct Index;
  PointList owned_;
  const PointList& points_;
  std::unique_ptr<Index> index_;
};

}  // namespace cloudshape::geometry
