// Cell keys numbered in order of arrival, and a value per key: the all-ones key (the flat map's
// empty marker, the cell (-1, -1)) is a key like any other.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "segment/detail/key_index.hpp"

namespace cloudshape::segment::detail {
namespace {

constexpr std::uint64_t kAllOnes = ~std::uint64_t{0};

TEST(KeyIndex, NumbersKeysInOrderOfArrivalAcrossGrowth) {
  KeyIndex index;  // no size expected: the map grows
  bool added = false;
  for (std::uint64_t k = 0; k < 1000; ++k) {
    EXPECT_EQ(index.index(k * 7919u, added), k);
    EXPECT_TRUE(added);
  }
  EXPECT_EQ(index.index(5 * 7919u, added), 5u);
  EXPECT_FALSE(added);
  EXPECT_EQ(index.size(), 1000u);
  EXPECT_EQ(index.find(999 * 7919u), 999u);
  EXPECT_EQ(index.find(1), KeyIndex::kAbsent);
}

TEST(KeyIndex, TheAllOnesKeyIsAKeyOfItsOwn) {
  KeyIndex index(4);
  bool added = false;
  EXPECT_EQ(index.find(kAllOnes), KeyIndex::kAbsent);
  EXPECT_EQ(index.index(3, added), 0u);
  EXPECT_EQ(index.index(kAllOnes, added), 1u);
  EXPECT_TRUE(added);
  EXPECT_EQ(index.index(kAllOnes, added), 1u);
  EXPECT_FALSE(added);
  EXPECT_EQ(index.find(kAllOnes), 1u);
  EXPECT_EQ(index.size(), 2u);
}

TEST(CellValues, KeepsTheFirstValueOfAKeyAndTheirOrder) {
  CellValues cells;
  EXPECT_TRUE(cells.empty());
  cells.try_emplace(kAllOnes, -0.5);
  cells.try_emplace(42, 1.25);
  cells.try_emplace(42, 9.0);  // a later value for a known key is not stored
  ASSERT_NE(cells.find(42), nullptr);
  EXPECT_EQ(*cells.find(42), 1.25);
  ASSERT_NE(cells.find(kAllOnes), nullptr);
  EXPECT_EQ(*cells.find(kAllOnes), -0.5);
  EXPECT_EQ(cells.find(7), nullptr);
  EXPECT_EQ(cells.values(), (std::vector<double>{-0.5, 1.25}));
  }

}  // namespace
}  // namespace cloudshape::segment::detail
