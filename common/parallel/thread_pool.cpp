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
    busy_workers_ = workers_.size();
    error_ = nullptr;
    ++generation_;
  }
  wake_.notify_all();
  take_blocks();
  std::exception_ptr error;
  {
    // Every worker leaves this generation before f (the caller's) goes out of scope.
    std::unique_lock<std::mutex> lock(state_mutex_);
    finished_.wait(lock, [this] { return busy_workers_ == 0; });
    job_ = nullptr;
    error = error_;
    error_ = nullptr;
  }
  if (error) std::rethrow_exception(error);
}

void ThreadPool::take_blocks() {
  for (std::size_t b = next_.fetch_add(1); b < blocks_; b = next_.fetch_add(1)) {
    try {
      (*job_)(b);
    } catch (...) {
      std::lock_guard<std::mutex> lock(state_mutex_);
      if (!error_) error_ = std::current_exception();
    }
  }
}

void ThreadPool::worker_loop() {
  std::size_t seen = 0;
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(state_mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
    }
    take_blocks();
    std::lock_guard<std::mutex> lock(state_mutex_);
    if (--busy_workers_ == 0) finished_.notify_one();
  }
}

}  // namespace cloudshape::parallel
