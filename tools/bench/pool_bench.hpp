// cloudshape-bench --pool: what a parallel run costs on the thread pool, against the same blocks
// run in order on the caller, for blocks from none to about a millisecond of work.
#pragma once

#include "parallel/thread_pool.hpp"

namespace cloudshape::bench {

struct PoolBenchOptions {
  parallel::ThreadPool* pool = nullptr;  // its size() blocks a run, one per thread
  int batches = 9;                       // the per-call figure is the median batch's
  bool json = false;
};

// Prints one row per block size: the block's work alone, a run of size() blocks in order on the
// caller and on the pool (microseconds a call), and their ratio. Returns the exit status.
int run_pool_bench(const PoolBenchOptions& options);

}  // namespace cloudshape::bench
