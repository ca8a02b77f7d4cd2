// A small fixed pool of worker threads that runs numbered blocks of work, passed explicitly to
// the stages that split; the caller works too, and a busy pool (a nested call) runs inline.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace cloudshape::parallel {

class ThreadPool {
 public:
  // `threads` in all, the calling thread included (it runs blocks while it waits); 0 means one
  // per core (std::thread::hardware_concurrency), 1 none besides the caller.
  explicit ThreadPool(std::size_t threads);
  ~ThreadPool();  // joins every worker
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  std::size_t size() const { return workers_.size() + 1; }

  // Calls f(b) once for every b in [0, blocks) and returns when all have run. Blocks are
  // handed out in increasing order to whichever thread is free, so f must write only what block
  // b owns. While another run_blocks holds the pool (a block that splits again), this one runs
  // its blocks in order on the calling thread: no deadlock, and the same results. The first
  // exception a block throws is rethrown here once every block has finished.
  void run_blocks(std::size_t blocks, const std::function<void(std::size_t)>& f);

 private:
  void worker_loop();
  void take_blocks(const std::function<void(std::size_t)>& f, std::size_t blocks);

  std::vector<std::thread> workers_;
  std::mutex run_mutex_;    // held by the run_blocks that owns the workers
  std::mutex state_mutex_;  // guards everything below but next_
  std::condition_variable wake_;
  std::condition_variable finished_;
  const std::function<void(std::size_t)>* job_ = nullptr;
  std::size_t blocks_ = 0;
  std::atomic<std::size_t> next_{0};
  std::size_t joined_workers_ = 0;  // workers inside take_blocks for the current job
  std::size_t generation_ = 0;
  bool stop_ = false;
  std::exception_ptr error_;
};

// Splits [0, n) into consecutive blocks of `grain` items (the last one shorter) and calls
// f(begin, end) for each; serially, in order, without a pool. The blocks depend on n and grain
// only, never on the thread count, so per-block results combined in block order are the same
// for any pool.
template <class F>
void for_blocks(ThreadPool* pool, std::size_t n, std::size_t grain, F&& f) {
  if (n == 0) return;
  grain = grain == 0 ? 1 : grain;
  const std::size_t blocks = (n + grain - 1) / grain;
  const auto block = [&](std::size_t b) { f(b * grain, b + 1 == blocks ? n : (b + 1) * grain); };
  if (pool == nullptr || blocks == 1) {
    for (std::size_t b = 0; b < blocks; ++b) block(b);
    return;
  }
  pool->run_blocks(blocks, block);
}

}  // namespace cloudshape::parallel
