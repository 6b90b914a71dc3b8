// A minimal parallel loop on std::thread: workers pull chunks of an index range from a shared
// counter (dynamic scheduling, so uneven elements balance out). The first exception thrown by any
// worker stops the others at their next chunk and is rethrown in the caller.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace styk::solver_detail {

inline int resolve_threads(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(hw);
}

// body(begin, end, worker) is called for consecutive chunks [begin, end) of [0, n); `worker` is in
// [0, threads) and lets the body use per-thread scratch space. Every `begin` is a multiple of
// `chunk` (one thread: a single call for [0, n)), so begin / chunk names a chunk's own output.
template <class Body>
void parallel_for(int n, int threads, int chunk, const Body& body) {
  if (n <= 0) return;
  chunk = std::max(chunk, 1);
  threads = std::max(1, std::min(threads, (n + chunk - 1) / chunk));
  if (threads == 1) {
    body(0, n, 0);
    return;
  }
  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&](int worker) {
    try {
      for (;;) {
        if (failed.load(std::memory_order_relaxed)) return;
        const int begin = next.fetch_add(chunk, std::memory_order_relaxed);
        if (begin >= n) return;
        body(begin, std::min(n, begin + chunk), worker);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace styk::solver_detail
