// Paced sends' deadlines (sim_client/pacing.h): an offset in seconds becomes a steady_clock
// time point exactly where it fits and without the int64 nanosecond overflow where it does
// not (a log spanning 1900-2199 paced in real time: 300 years > the clock's 292).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "sim_client/pacing.h"

namespace cloudsvc::sim {
namespace {

using std::chrono::steady_clock;

TEST(Pacing, OffsetsBecomeDeadlinesWithoutOverflow) {
  const steady_clock::time_point start = steady_clock::now();
  EXPECT_EQ(due_after(start, 1.5), start + std::chrono::milliseconds(1500));
  EXPECT_EQ(due_after(start, 0.0), start);
  EXPECT_EQ(due_after(start, -3.0), start);  // already due
  EXPECT_EQ(due_after(start, std::nan("")), start);
  const steady_clock::time_point cap = due_after(start, kMaxPacingOffset_s);
  EXPECT_GT(cap, start);
  // 300 years (1900-2199) and beyond: held at the cap, later than start, never wrapped
  for (double s : {300.0 * 365.25 * 86400.0, 1e300, static_cast<double>(INFINITY)}) {
    EXPECT_EQ(due_after(start, s), cap) << s;
  }
  EXPECT_NEAR(std::chrono::duration<double>(cap - start).count(), kMaxPacingOffset_s, 1.0);
}

}  // namespace
}  // namespace cloudsvc::sim
