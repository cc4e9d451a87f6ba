#pragma once
// Runs independent tasks on a few threads (std::thread); results go to per-index slots, so they
// do not depend on the number of threads. Used by the sim library and the jobs.
#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace cordgrasp {

/// Calls fn(i) for i in [0, n) on min(jobs, n) threads (the caller's thread when 1), each index
/// once, in no fixed order. The first exception thrown by fn stops the remaining indices and is
/// rethrown here after every thread has finished.
template <typename F>
void parallel_for(int n, int jobs, F&& fn) {
  const int threads = std::max(1, std::min(jobs, n));
  if (threads == 1) {
    for (int i = 0; i < n; ++i) fn(i);
    return;
  }
  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&]() {
    for (int i = next++; i < n && !failed; i = next++) {
      try {
        fn(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

/// Calls report(i) for i = 0, 1, ... in order as soon as tasks 0..i have all finished; call
/// finished(i) from any thread when task i is done.
class InOrderReporter {
 public:
  template <typename R>
  InOrderReporter(int n, R report) : done_(static_cast<size_t>(n), false), report_(report) {}
  void finished(int i) {
    const std::lock_guard<std::mutex> lock(mutex_);
    done_[static_cast<size_t>(i)] = true;
    while (next_ < static_cast<int>(done_.size()) && done_[static_cast<size_t>(next_)])
      report_(next_++);
  }

 private:
  std::mutex mutex_;
  std::vector<bool> done_;
  std::function<void(int)> report_;
  int next_ = 0;
};

}  // namespace cordgrasp
