// The thread pool runs every block exactly once, whatever the thread count, survives a block
// that splits again, and hands a block's exception to the caller.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "parallel/thread_pool.hpp"

namespace cloudshape::parallel {
namespace {

TEST(ThreadPool, SizeCountsTheCaller) {
  EXPECT_EQ(ThreadPool(1).size(), 1u);
  EXPECT_EQ(ThreadPool(3).size(), 3u);
  EXPECT_GE(ThreadPool(0).size(), 1u);  // one per core
}

TEST(ThreadPool, EveryBlockRunsOnceForAnyThreadCount) {
  for (std::size_t threads : {1u, 2u, 3u, 8u}) {
    ThreadPool pool(threads);
    for (int round = 0; round < 50; ++round) {  // reuse: every generation must finish cleanly
      std::vector<int> runs(997, 0);
      pool.run_blocks(runs.size(), [&](std::size_t b) { ++runs[b]; });
      EXPECT_EQ(std::count(runs.begin(), runs.end(), 1), 997) << threads << " threads, round " << round;
    }
  }
}

// Runs so short that the caller often finishes every block before a worker wakes: the caller
// returns without waiting for that worker, which must then neither run a block of a job whose
// function is gone (each run's is a new object) nor miss the next run.
TEST(ThreadPool, BackToBackTinyRunsRunEachBlockOnceAndNoneLate) {
  for (std::size_t threads : {2u, 4u}) {
    ThreadPool pool(threads);
    std::atomic<int> late{0};
    for (int round = 0; round < 20000; ++round) {
      auto runs = std::make_unique<std::vector<std::atomic<int>>>(3);
      std::atomic<bool> returned{false};
      const std::function<void(std::size_t)> job = [&runs, &returned, &late](std::size_t b) {
        if (returned) ++late;
        ++(*runs)[b];
      };
      pool.run_blocks(runs->size(), job);
      returned = true;
      for (std::size_t b = 0; b < runs->size(); ++b)
        ASSERT_EQ((*runs)[b].load(), 1)
            << threads << " threads, round " << round << ", block " << b;
    }
    EXPECT_EQ(late.load(), 0) << threads << " threads";
  }
}

TEST(ThreadPool, ForBlocksCoversTheRangeInBlocksFixedByTheGrain) {
  ThreadPool pool(3);
  std::vector<std::pair<std::size_t, std::size_t>> blocks(4);
  std::vector<int> covered(10, 0);
  for_blocks(&pool, 10, 3, [&](std::size_t begin, std::size_t end) {
    blocks[begin / 3] = {begin, end};
    for (std::size_t i = begin; i < end; ++i) ++covered[i];
  });
  EXPECT_EQ(blocks, (std::vector<std::pair<std::size_t, std::size_t>>{{0, 3}, {3, 6}, {6, 9}, {9, 10}}));
  EXPECT_EQ(std::count(covered.begin(), covered.end(), 1), 10);
  int serial = 0;
  for_blocks(nullptr, 10, 4, [&](std::size_t begin, std::size_t end) { serial += static_cast<int>(end - begin); });
  EXPECT_EQ(serial, 10);
}

TEST(ThreadPool, ANestedCallRunsInlineAndFinishes) {
  ThreadPool pool(2);
  std::vector<long> sums(8, 0);
  pool.run_blocks(sums.size(), [&](std::size_t outer) {
    std::vector<long> part(100, 0);
    pool.run_blocks(part.size(), [&](std::size_t inner) { part[inner] = static_cast<long>(outer * 100 + inner); });
    sums[outer] = std::accumulate(part.begin(), part.end(), 0L);
  });
  for (std::size_t o = 0; o < sums.size(); ++o) EXPECT_EQ(sums[o], static_cast<long>(o * 10000 + 4950));
}

TEST(ThreadPool, ABlocksExceptionReachesTheCallerAfterEveryBlockRan) {
  ThreadPool pool(3);
  std::atomic<int> ran{0};
  EXPECT_THROW(pool.run_blocks(64,
                               [&](std::size_t b) {
                                 ++ran;
                                 if (b == 17) throw std::runtime_error("block 17");
                               }),
               std::runtime_error);
  EXPECT_EQ(ran.load(), 64);
  // The pool still works afterwards.
  std::atomic<int> again{0};
  pool.run_blocks(10, [&](std::size_t) { ++again; });
  EXPECT_EQ(again.load(), 10);
}

}  // namespace
}  // namespace cloudshape::parallel
