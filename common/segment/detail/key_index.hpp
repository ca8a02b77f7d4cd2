// Distinct 64-bit cell keys numbered in order of arrival, on the flat cell map: a plane's in-plane
// cells (occupied area, row and column spans, a footprint's cell heights) without a node per key.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/detail/flat_hash.hpp"

namespace cloudshape::segment::detail {

// The flat map's empty-slot marker (all bits set) is a key of its own here: the cell (-1, -1).
class KeyIndex {
 public:
  static constexpr std::uint32_t kAbsent = geometry::detail::CellMap::kAbsent;
  explicit KeyIndex(std::size_t expected = 0) : map_(expected) {}
  // The key's number; `added` tells whether it is new (numbered size() before the call).
  std::uint32_t index(std::uint64_t key, bool& added) {
    if (key == kAllOnes) {
      added = all_ones_ == kAbsent;
      if (added) all_ones_ = size_++;
      return all_ones_;
    }
    const std::uint32_t i = map_.find_or_insert(key, size_, added);
    if (added) ++size_;
    return i;
  }
  std::uint32_t find(std::uint64_t key) const { return key == kAllOnes ? all_ones_ : map_.find(key); }
  std::size_t size() const { return size_; }

 private:
  static constexpr std::uint64_t kAllOnes = ~std::uint64_t{0};
  geometry::detail::CellMap map_;
  std::uint32_t all_ones_ = kAbsent;
  std::uint32_t size_ = 0;
};

// A value per cell key, the first one stored for a key kept.
class CellValues {
 public:
  explicit CellValues(std::size_t expected = 0) : index_(expected) {}
  void try_emplace(std::uint64_t key, double value) {
    bool added = false;
    index_.index(key, added);
    if (added) values_.push_back(value);
  }
  const double* find(std::uint64_t key) const {
    const std::uint32_t i = index_.find(key);
    return i == KeyIndex::kAbsent ? nullptr : &values_[i];
  }
  bool empty() const { return values_.empty(); }
  // In order of arrival.
  const std::vector<double>& values() const { return values_; }

 private:
  KeyIndex index_;
  std::vector<double> values_;
};

}  // namespace cloudshape::segment::detail
