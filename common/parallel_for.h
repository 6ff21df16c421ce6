// The one parallel-for of the project: calls fn(i) for every i in [0, n) on worker threads.
//
// Thread count: parallel_for(n, threads, fn) runs on resolve_threads(threads) threads
// (never more than n), the calling thread being one of them. threads > 0 is taken as is;
// threads <= 0 (the default 0 of every option struct's `threads` field) means all the
// machine's hardware threads, std::thread::hardware_concurrency() (at least 1 when it is
// unknown). Note: that is the machine's thread count, not a CPU quota or affinity mask of
// the process; pass an explicit count where those are smaller.
//
// Scheduling: indices are handed out in increasing order, one at a time, from a shared
// atomic counter (dynamic scheduling), which balances items of unequal cost (image rows
// with and without clouds, table rows near the horizon, Monte Carlo chunks). Which thread
// runs which index is unspecified, so a result that must not depend on the thread count
// has to make fn(i) depend on i only: its own output slot, its own random stream seeded
// from i, and reductions over per-index partial results summed by the caller in index
// order (renderer/reference/atmosphere_monte_carlo.cpp, renderer/model/slab_monte_carlo.cpp).
//
// Threads are started per call and joined before it returns (no shared pool): every caller
// is coarse (one image, one table, one noise volume, one Monte Carlo estimate: milliseconds
// to seconds), against ~20-50 us to start and join a thread. If fn throws, indices not yet
// started are skipped, and the first exception is rethrown in the caller once every thread
// has finished. If a thread cannot be started, the threads already running (at least the
// caller) do the work.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace cloudsvc {

// Hardware threads of the machine (std::thread::hardware_concurrency()), at least 1.
inline int hardware_threads() {
  static const int n = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return n;
}

// The `threads` value for "every hardware thread" (the default of the option structs).
inline constexpr int kAllThreads = 0;

// The thread count a `threads` option stands for: itself if > 0, else hardware_threads().
inline int resolve_threads(int threads) { return threads > 0 ? threads : hardware_threads(); }

// Calls fn(i) exactly once for every i in [0, n) (nothing for n <= 0) on
// min(resolve_threads(threads), n) threads, and returns when every call has returned.
// fn must be safe to call concurrently for different i.
template <typename Fn>
void parallel_for(int n, int threads, const Fn& fn) {
  if (n <= 0) return;
  const int workers = std::min(resolve_threads(threads), n);
  if (workers == 1) {
    for (int i = 0; i < n; ++i) fn(i);
    return;
  }
  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto work = [&] {
    for (int i = next.fetch_add(1, std::memory_order_relaxed); i < n && !failed.load(std::memory_order_relaxed);
         i = next.fetch_add(1, std::memory_order_relaxed)) {
      try {
        fn(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        failed.store(true, std::memory_order_relaxed);
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(workers - 1));
  try {
    for (int t = 1; t < workers; ++t) pool.emplace_back(work);
  } catch (const std::system_error&) {
    // no more threads available: the ones running (and this one) share the work
  }
  work();
  for (std::thread& th : pool) th.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace cloudsvc
