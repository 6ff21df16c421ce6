// Splits a loop over rows [0, n) between threads, rows interleaved (image rows and table
// rows have unequal costs). Each row is computed independently, so results do not depend
// on the thread count.
#pragma once

#include <algorithm>
#include <thread>
#include <vector>

namespace cloudsvc::reference {

template <typename Fn>
void parallel_rows(int n, int threads, const Fn& fn) {
  threads = std::clamp(threads, 1, std::max(1, n));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
    pool.emplace_back([&fn, n, threads, t] {
      for (int row = t; row < n; row += threads) fn(row);
    });
  for (int row = 0; row < n; row += threads) fn(row);
  for (std::thread& th : pool) th.join();
}

}  // namespace cloudsvc::reference
