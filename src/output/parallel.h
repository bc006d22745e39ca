#pragma once
// fn(0) … fn(n−1) on `jobs` threads. Each call writes only its own slot of the caller's
// results, so the outcome does not depend on the order in which threads pick the work.
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace epure::output {

template <class Fn>
void parallel_for(int n, int jobs, Fn&& fn) {
  if (jobs <= 1 || n <= 1) {
    for (int i = 0; i < n; ++i) fn(i);
    return;
  }
  std::atomic<int> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&] {
    for (int i = next++; i < n; i = next++) {
      try {
        fn(i);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
      }
    }
  };
  {
    std::vector<std::jthread> threads;
    for (int t = 1; t < jobs && t < n; ++t) threads.emplace_back(worker);
    worker();
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace epure::output
