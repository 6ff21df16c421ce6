// Splits a loop over rows [0, n) between worker threads (internal to weather/).
// Each row is computed independently, so the result does not depend on the thread count.
#pragma once

#include <algorithm>
#include <thread>
#include <vector>

namespace cloudsvc::weather::detail {

// Calls fn(row) for every row in [0, n), rows interleaved over `threads` threads
// (interleaving balances rows of unequal cost, e.g. near the poles).
template <typename Fn>
void parallel_for_rows(int n, int threads, const Fn& fn) {
  threads = std::clamp(threads, 1, std::max(1, n));
  if (threads == 1) {
    for (int r = 0; r < n; ++r) fn(r);
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (int t = 1; t < threads; ++t) {
    pool.emplace_back([&fn, n, threads, t] {
      for (int r = t; r < n; r += threads) fn(r);
    });
  }
  for (int r = 0; r < n; r += threads) fn(r);
  for (std::thread& th : pool) th.join();
}

// Worker threads for one-off generation at start-up: 2 (the target machine has 2 cores),
// or 1 on a single-core machine.
inline int generation_threads() {
  return std::thread::hardware_concurrency() == 1 ? 1 : 2;
}

}  // namespace cloudsvc::weather::detail
