// common/parallel_for.h: every index visited exactly once for any n and thread count
// (including n = 0 and n < threads), the thread count honoured, exceptions propagated.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "common/parallel_for.h"

namespace cloudsvc {
namespace {

TEST(ParallelFor, VisitsEveryIndexExactlyOnce) {
  for (int n : {0, 1, 2, 3, 4, 5, 7, 16, 100, 1000}) {
    for (int threads : {0, 1, 2, 3, 5, 16, 64}) {
      std::vector<std::atomic<int>> visits(static_cast<std::size_t>(n));
      for (auto& v : visits) v = 0;
      parallel_for(n, threads, [&](int i) {
        ASSERT_GE(i, 0);
        ASSERT_LT(i, n);
        visits[static_cast<std::size_t>(i)].fetch_add(1);
      });
      for (int i = 0; i < n; ++i)
        EXPECT_EQ(visits[static_cast<std::size_t>(i)].load(), 1) << "n " << n << " threads " << threads << " i " << i;
    }
  }
}

TEST(ParallelFor, NegativeCountCallsNothing) {
  int calls = 0;
  parallel_for(-3, 2, [&](int) { ++calls; });
  EXPECT_EQ(calls, 0);
}

// Never more threads than asked for, nor than indices; one thread = the caller's.
TEST(ParallelFor, UsesAtMostTheRequestedThreads) {
  for (int n : {1, 3, 50}) {
    for (int threads : {1, 2, 5}) {
      std::mutex m;
      std::set<std::thread::id> ids;
      parallel_for(n, threads, [&](int) {
        std::this_thread::sleep_for(std::chrono::microseconds(200));  // give every worker a turn
        const std::lock_guard<std::mutex> lock(m);
        ids.insert(std::this_thread::get_id());
      });
      EXPECT_GE(ids.size(), 1u);
      EXPECT_LE(ids.size(), static_cast<std::size_t>(std::min(n, threads))) << "n " << n << " threads " << threads;
      if (threads == 1) {
        EXPECT_EQ(*ids.begin(), std::this_thread::get_id());
      }
    }
  }
}

TEST(ParallelFor, ZeroMeansAllHardwareThreads) {
  const unsigned hw = std::thread::hardware_concurrency();
  EXPECT_EQ(hardware_threads(), hw == 0 ? 1 : static_cast<int>(hw));
  EXPECT_EQ(resolve_threads(0), hardware_threads());
  EXPECT_EQ(resolve_threads(-1), hardware_threads());
  EXPECT_EQ(resolve_threads(1), 1);
  EXPECT_EQ(resolve_threads(3), 3);
  EXPECT_GE(hardware_threads(), 1);
}

// The first exception reaches the caller after every thread has finished; indices after
// the failure may be skipped, none is visited twice.
TEST(ParallelFor, RethrowsTheExceptionOfAnIndex) {
  for (int threads : {1, 2, 5}) {
    std::vector<std::atomic<int>> visits(200);
    for (auto& v : visits) v = 0;
    EXPECT_THROW(parallel_for(200, threads,
                              [&](int i) {
                                visits[static_cast<std::size_t>(i)].fetch_add(1);
                                if (i == 17) throw std::runtime_error("index 17");
                              }),
                 std::runtime_error);
    EXPECT_EQ(visits[17].load(), 1);
    for (const auto& v : visits) EXPECT_LE(v.load(), 1);
  }
}

}  // namespace
}  // namespace cloudsvc
