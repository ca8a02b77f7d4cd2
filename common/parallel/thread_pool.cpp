#include "parallel/thread_pool.hpp"

#include <algorithm>

namespace cloudshape::parallel {

ThreadPool::ThreadPool(std::size_t threads) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  workers_.reserve(threads - 1);
  for (std::size_t i = 1; i < threads; ++i) workers_.emplace_back([this] { worker_loop(); });
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& w : workers_) w.join();
}

void ThreadPool::run_blocks(std::size_t blocks, const std::function<void(std::size_t)>& f) {
  std::unique_lock<std::mutex> owner(run_mutex_, std::try_to_lock);
  if (!owner.owns_lock() || workers_.empty() || blocks <= 1) {
    for (std::size_t b = 0; b < blocks; ++b) f(b);
    return;
  }
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    job_ = &f;
    blocks_ = blocks;
    next_.store(0);
    error_ = nullptr;
    ++generation_;
  }
  wake_.notify_all();
  take_blocks(f, blocks);
  std::exception_ptr error;
  {
    // The job is withdrawn before the wait: a worker that wakes only now (a VM's wake-up can
    // take longer than all the blocks) finds nothing and is not waited for; the caller waits
    // only for those that joined, and they leave before f (the caller's) goes out of scope.
    std::unique_lock<std::mutex> lock(state_mutex_);
    job_ = nullptr;
    finished_.wait(lock, [this] { return joined_workers_ == 0; });
    error = error_;
    error_ = nullptr;
  }
  if (error) std::rethrow_exception(error);
}

void ThreadPool::take_blocks(const std::function<void(std::size_t)>& f, std::size_t blocks) {
  for (std::size_t b = next_.fetch_add(1); b < blocks; b = next_.fetch_add(1)) {
    try {
      f(b);
    } catch (...) {
      std::lock_guard<std::mutex> lock(state_mutex_);
      if (!error_) error_ = std::current_exception();
    }
  }
}

void ThreadPool::worker_loop() {
  std::size_t seen = 0;
  for (;;) {
    const std::function<void(std::size_t)>* job = nullptr;
    std::size_t blocks = 0;
    {
      std::unique_lock<std::mutex> lock(state_mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      if (job_ == nullptr) continue;  // its caller ran every block already
      job = job_;
      blocks = blocks_;
      ++joined_workers_;
    }
    take_blocks(*job, blocks);
    std::lock_guard<std::mutex> lock(state_mutex_);
    if (--joined_workers_ == 0) finished_.notify_one();
  }
}

}  // namespace cloudshape::parallel
