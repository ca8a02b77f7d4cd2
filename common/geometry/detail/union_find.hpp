// Disjoint sets over 0..n-1 with path halving: connected components of raster cells
// (plane patches, separate objects).
#pragma once

#include <cstdint>
#include <numeric>
#include <vector>

namespace cloudshape::geometry::detail {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }

  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<std::uint32_t> parent_;
};

}  // namespace cloudshape::geometry::detail
