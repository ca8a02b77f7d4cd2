// cloudshape-inject's record of the clouds awaiting their result: overdue ones come back
// oldest first, and a result that arrives while a cloud is being sent again completes it.
#include "../../tools/inject/pending_clouds.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace cloudshape::inject {
namespace {
using namespace std::chrono_literals;

PendingCloud cloud(std::uint64_t id, Clock::time_point sent) { return {id, "c.pcd", "c.pcd", 0, sent, 1}; }

TEST(InjectPendingClouds, OverdueCloudsComeBackOldestFirst) {
  PendingClouds pending;
  const Clock::time_point t0 = Clock::now();
  pending.sent(cloud(1, t0 + 1s));
  pending.sent(cloud(2, t0));
  EXPECT_FALSE(pending.resend_overdue(t0 + 2s, 3s));
  const auto first = pending.resend_overdue(t0 + 3s, 3s);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->id, 2u);
  EXPECT_EQ(first->attempts, 2);
  const auto second = pending.resend_overdue(t0 + 4s, 3s);
  ASSERT_TRUE(second);
  EXPECT_EQ(second->id, 1u);
  EXPECT_FALSE(pending.resend_overdue(t0 + 4s, 3s));  // both were just sent again
  EXPECT_EQ(pending.size(), 2u);
}

TEST(InjectPendingClouds, AResultDuringAResendCompletesTheCloud) {
  PendingClouds pending;
  const Clock::time_point t0 = Clock::now();
  pending.sent(cloud(5, t0));
  ASSERT_TRUE(pending.resend_overdue(t0 + 10s, 3s));
  pending.complete(5, "c.pcd");  // the first attempt's result, while the resend is written
  EXPECT_EQ(pending.size(), 0u);
  EXPECT_FALSE(pending.resend_overdue(t0 + 60s, 3s));
}

TEST(InjectPendingClouds, OnlyTheSameSourceCompletesACloud) {
  PendingClouds pending;
  pending.sent(cloud(5, Clock::now()));
  pending.complete(5, "other.pcd");  // another injector's cloud 5
  EXPECT_EQ(pending.size(), 1u);
}

// The sender waits for room; a result makes room at once, not at the end of the wait.
TEST(InjectPendingClouds, AResultWakesASenderWaitingForRoom) {
  PendingClouds pending;
  pending.sent(cloud(1, Clock::now()));
  pending.sent(cloud(2, Clock::now()));
  EXPECT_TRUE(pending.wait_below(3, 0s));
  EXPECT_FALSE(pending.wait_below(2, 50ms));
  const auto started = Clock::now();
  std::thread result([&] {
    std::this_thread::sleep_for(100ms);
    pending.complete(1, "c.pcd");
  });
  EXPECT_TRUE(pending.wait_below(2, 30s));
  const auto waited = Clock::now() - started;
  result.join();
  EXPECT_GE(waited, 90ms);
  EXPECT_LT(waited, 20s) << "woken by the timeout, not by the result";
  EXPECT_EQ(pending.size(), 1u);
}

}  // namespace
}  // namespace cloudshape::inject
