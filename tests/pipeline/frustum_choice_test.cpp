// solve_object fits a frustum only where it can change the choice among the other candidates: the
// skip must hold exactly where no frustum's share of explained points (up to all) changes it.
#include <gtest/gtest.h>

#include <vector>

#include "pipeline/solve.hpp"

namespace cloudshape::pipeline {
namespace {

constexpr double kMargin = 0.02;

// The candidates solve_object keeps in the running when the most explained is `most`: those within
// kMargin of it, as its own test writes it.
std::vector<bool> in_running(const std::vector<double>& explained, double most) {
  std::vector<bool> out;
  for (double e : explained) out.push_back(!(e < most - kMargin));
  return out;
}

// Brute force over the frustum's possible shares (0 to 1 in steps finer than any test's values):
// whether any of them changes which candidates are in the running, or leaves none of them.
bool changes_running(const std::vector<double>& explained) {
  double most = -1.0;
  for (double e : explained) most = std::max(most, e);
  const std::vector<bool> without = in_running(explained, most);
  for (int k = 0; k <= 100000; ++k) {
    const double frustum = k / 100000.0;
    const std::vector<bool> with = in_running(explained, std::max(most, frustum));
    bool any = false;
    for (bool b : with) any = any || b;
    if (with != without || !any) return true;
  }
  return false;
}

TEST(FrustumChoice, NotFittedWhereAnotherExplainsNearlyEveryPoint) {
  EXPECT_FALSE(detail::frustum_may_matter({1.0}, kMargin));
  EXPECT_FALSE(detail::frustum_may_matter({0.2409, 0.99}, kMargin));
  // 0.979 is out of the running at 1.0 and at 0.999 alike.
  EXPECT_FALSE(detail::frustum_may_matter({1.0, 0.979}, kMargin));
}

TEST(FrustumChoice, FittedWhereItCouldExplainClearlyMore) {
  EXPECT_TRUE(detail::frustum_may_matter({0.2409, 0.9431}, kMargin));  // the 100k cone's shares
  EXPECT_TRUE(detail::frustum_may_matter({}, kMargin));
}

TEST(FrustumChoice, FittedWhereItCouldPushAnotherOutOfTheRunning) {
  // At 0.99 the 0.975 is in the running; a frustum explaining every point pushes it out.
  EXPECT_TRUE(detail::frustum_may_matter({0.99, 0.975}, kMargin));
}

TEST(FrustumChoice, AgreesWithEveryShareAFrustumCouldExplain) {
  const std::vector<std::vector<double>> cases = {
      {1.0}, {0.99}, {0.98}, {0.97}, {0.5}, {1.0, 0.979}, {1.0, 0.985}, {0.99, 0.975}, {0.99, 0.95},
      {0.985, 0.5, 0.97}, {0.981, 0.9}, {0.3, 0.2}};
  for (const auto& explained : cases) {
    EXPECT_EQ(detail::frustum_may_matter(explained, kMargin), changes_running(explained))
        << "first share " << explained.front() << " of " << explained.size();
  }
}

}  // namespace
}  // namespace cloudshape::pipeline
