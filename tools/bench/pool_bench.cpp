#include "pool_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <vector>

#include "bench_stats.hpp"

namespace cloudshape::bench {
namespace {

// A block's work: a chain of dependent multiply-adds (the compiler can neither drop nor
// vectorise it), written where no other block writes.
void work(std::size_t steps, double& slot) {
  double x = slot;
  for (std::size_t i = 0; i < steps; ++i) x = x * 0.999999 + 1e-6;
  slot = x;
}

// Microseconds a call of `blocks` blocks of `steps` each, the `quantile` (0.5: the median, 0: the
// fastest) of `batches` batches of `calls` calls (one warm-up batch first).
double per_call_us(parallel::ThreadPool* pool, std::size_t blocks, std::size_t steps,
                   std::size_t calls, int batches, double quantile = 0.5) {
  std::vector<double> slots(blocks * 8, 1.0);  // a cache line a block
  std::vector<double> samples;
  for (int b = -1; b < batches; ++b) {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t c = 0; c < calls; ++c)
      parallel::for_blocks(pool, blocks, 1,
                           [&](std::size_t i, std::size_t) { work(steps, slots[i * 8]); });
    const double us =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    if (b >= 0) samples.push_back(us / static_cast<double>(calls));
  }
  return percentile(samples, quantile);
}

}  // namespace

int run_pool_bench(const PoolBenchOptions& options) {
  const std::size_t threads = options.pool != nullptr ? options.pool->size() : 1;
  const std::size_t blocks = threads;
  nlohmann::json rows = nlohmann::json::array();
  if (!options.json) {
    std::printf(
        "thread pool, %zu threads, %zu blocks a run, median of %d batches (microseconds a call; a "
        "block's work: the fastest of 5)\n",
        threads, blocks, options.batches);
    std::printf("%12s %14s %14s %10s\n", "block work", "in order", "on the pool", "speed-up");
  }
  for (std::size_t steps : {0u, 1000u, 10000u, 100000u, 400000u}) {
    // A block's own time: the fastest of five batches, the one least interrupted by whatever else
    // runs on the machine. Calls for about 20 ms of work in order a batch: from 20 (the longest
    // blocks) to 100 000 (empty ones).
    const double block_us = per_call_us(nullptr, 1, steps, 100, 5, 0.0);
    const auto calls = static_cast<std::size_t>(std::clamp(
        20000.0 / std::max(1e-3, block_us * static_cast<double>(blocks)), 20.0, 100000.0));
    const double serial = per_call_us(nullptr, blocks, steps, calls, options.batches);
    const double pooled = per_call_us(options.pool, blocks, steps, calls, options.batches);
    const double speedup = pooled > 0.0 ? serial / pooled : 0.0;
    if (options.json) {
      rows.push_back({{"block_steps", steps},
                      {"block_us", block_us},
                      {"in_order_us", serial},
                      {"pool_us", pooled},
                      {"speedup", speedup}});
    } else {
      std::printf("%9.2f us %11.2f us %11.2f us %9.2fx\n", block_us, serial, pooled, speedup);
    }
  }
  if (options.json)
    std::printf(
        "%s\n",
        nlohmann::json{{"threads", threads}, {"blocks", blocks}, {"rows", rows}}.dump(2).c_str());
  return 0;
}

}  // namespace cloudshape::bench
