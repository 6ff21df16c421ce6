// Shared-memory frame ring: a concurrent reader never sees a torn frame, readers that die
// hold nothing, the segment is removed by its owner and protected while the owner lives.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <ctime>
#include <stdexcept>
#include <thread>
#include <vector>

#include "protocol/shm/cloudsvc_shm.h"
#include "protocol/shm/shm_frame_reader.h"
#include "protocol/shm/shm_frame_writer.h"

namespace cloudsvc {
namespace {

std::string unique_name(const char* tag) { return std::string("cloudsvc-test-") + tag + "-" + std::to_string(::getpid()); }

// Every byte of frame n is (n & 0xff) and the pose echo carries n: a torn copy mixes
// two frames and is detected.
TEST(ShmRing, ConcurrentReaderNeverSeesATornFrame) {
  const std::string name = unique_name("torn");
  const int w = 256, h = 128;
  ShmFrameWriter writer(name, w, h, 0600, 3);  // owner read+write, 3 slots
  std::atomic<bool> done{false};
  std::atomic<int> frames_read{0}, torn{0};
  std::thread reader_thread([&] {
    char err[256] = {};
    cloudsvc_shm_reader* r = cloudsvc_shm_open(name.c_str(), err, sizeof err);
    ASSERT_NE(r, nullptr) << err;
    std::vector<std::uint8_t> buf(static_cast<size_t>(w) * h * 8);
    cloudsvc_shm_slot info{};
    std::uint64_t last = 0;
    while (!done.load()) {
      const int rc = cloudsvc_shm_read_latest(r, last, &info, buf.data(), buf.size());
      ASSERT_GE(rc, 0);
      if (rc == 0) continue;
      ASSERT_GT(info.frame_number, last);
      last = info.frame_number;
      const auto expect = static_cast<std::uint8_t>(info.frame_number & 0xff);
      bool ok = info.lat_deg == static_cast<double>(info.frame_number);
      for (std::size_t i = 0; i < info.pixel_bytes && ok; ++i) ok = buf[i] == expect;
      if (!ok) torn.fetch_add(1);
      frames_read.fetch_add(1);
    }
    cloudsvc_shm_close(r);
  });
  // Write at least 3000 frames and keep writing until the reader has copied 100 of them
  // while the writer runs (a loaded 2-core CI machine may starve the reader thread for a
  // while); the time cap only stops a broken reader from hanging the test.
  std::vector<std::uint8_t> px(static_cast<size_t>(w) * h * 8);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  for (std::uint64_t n = 1;
       n <= 3000 || (frames_read.load() < 100 && std::chrono::steady_clock::now() < give_up); ++n) {
    std::fill(px.begin(), px.end(), static_cast<std::uint8_t>(n & 0xff));
    ShmFrameMeta meta;
    meta.frame_number = n;
    meta.lat_deg = static_cast<double>(n);
    writer.write(meta, CLOUDSVC_SHM_RGBA16F_LINEAR, w, h, px.data(), static_cast<size_t>(w) * 8);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  done = true;
  reader_thread.join();
  EXPECT_EQ(torn.load(), 0);
  EXPECT_GE(frames_read.load(), 100);
}

TEST(ShmRing, ReaderThatDiesHoldsNothing) {
  const std::string name = unique_name("die");
  ShmFrameWriter writer(name, 64, 32, 0600, 3);  // owner read+write, 3 slots
  std::vector<std::uint8_t> px(64 * 32 * 4, 7);
  ShmFrameMeta meta;
  meta.frame_number = 1;
  writer.write(meta, CLOUDSVC_SHM_RGBA8_SRGB, 64, 32, px.data(), 64 * 4);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // a reader that spins until killed
    ShmFrameReader r(name);
    ShmFrame f;
    for (;;) r.read_latest(0, f);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  for (std::uint64_t n = 2; n < 10; ++n) {
    meta.frame_number = n;
    writer.write(meta, CLOUDSVC_SHM_RGBA8_SRGB, 64, 32, px.data(), 64 * 4);
  }
  ShmFrameReader r(name);
  ShmFrame f;
  ASSERT_TRUE(r.read_latest(0, f));
  EXPECT_EQ(f.info.frame_number, 9u);
  EXPECT_EQ(f.info.width, 64u);
  EXPECT_EQ(f.pixels.size(), 64u * 32u * 4u);
}

TEST(ShmRing, OwnerRemovesSegmentAndLiveOwnerIsProtected) {
  const std::string name = unique_name("own");
  {
    ShmFrameWriter writer(name, 16, 16);
    EXPECT_NO_THROW(ShmFrameReader r(name));
  }
  EXPECT_THROW(ShmFrameReader r(name), std::runtime_error) << "segment must be removed";

  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // another live service owning the name
    ShmFrameWriter w(name, 16, 16);
    char c = 1;
    (void)!::write(ready[1], &c, 1);
    ::pause();
    _exit(0);
  }
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  EXPECT_THROW(ShmFrameWriter(name, 16, 16), std::runtime_error);
  ::kill(child, SIGKILL);  // dies without cleaning up: a stale segment
  ::waitpid(child, nullptr, 0);
  EXPECT_NO_THROW(ShmFrameWriter(name, 16, 16)) << "a stale segment is taken over";
}

TEST(ShmRing, RejectsOversizeFramesAndBadNames) {
  EXPECT_THROW(ShmFrameWriter("bad/name", 16, 16), std::runtime_error);
  EXPECT_THROW(ShmFrameWriter("..", 16, 16), std::runtime_error);
  ShmFrameWriter writer(unique_name("size"), 16, 16);
  std::vector<std::uint8_t> px(32 * 32 * 8);
  EXPECT_THROW(writer.write({}, CLOUDSVC_SHM_RGBA16F_LINEAR, 32, 32, px.data(), 32 * 8), std::runtime_error);
}

std::int64_t realtime_ns() {
  timespec ts{};
  ::clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

// Every slot carries CLOCK_REALTIME of its publication (layout version 2): between the
// clock before and after write(), and the same through the C++ reader (with and without
// pixels) and the C ABI.
TEST(ShmRing, SlotCarriesItsPublishTime) {
  const std::string name = unique_name("publish");
  ShmFrameWriter writer(name, 16, 8);
  ShmFrameReader reader(name);
  char err[256] = {};
  cloudsvc_shm_reader* c = cloudsvc_shm_open(name.c_str(), err, sizeof err);
  ASSERT_NE(c, nullptr) << err;
  std::vector<std::uint8_t> px(16 * 8 * 4, 7);
  std::int64_t previous = 0;
  for (std::uint64_t n = 1; n <= 3; ++n) {
    ShmFrameMeta meta;
    meta.frame_number = n;
    const std::int64_t before = realtime_ns();
    writer.write(meta, CLOUDSVC_SHM_RGBA8_SRGB, 16, 8, px.data(), 16 * 4);
    const std::int64_t after = realtime_ns();
    ShmFrame f;
    ASSERT_TRUE(reader.read_latest(n - 1, f));
    EXPECT_EQ(f.info.frame_number, n);
    EXPECT_GE(f.info.publish_unix_ns, before);
    EXPECT_LE(f.info.publish_unix_ns, after);
    EXPECT_GE(f.info.publish_unix_ns, previous);
    previous = f.info.publish_unix_ns;
    cloudsvc_shm_slot header{};
    ASSERT_TRUE(reader.read_latest_header(n - 1, header));
    EXPECT_EQ(header.frame_number, n);
    EXPECT_EQ(header.publish_unix_ns, f.info.publish_unix_ns);
    EXPECT_FALSE(reader.read_latest_header(n, header)) << "no frame newer than the newest";
    cloudsvc_shm_slot info{};
    ASSERT_EQ(cloudsvc_shm_read_latest(c, n - 1, &info, px.data(), px.size()), 1);
    EXPECT_EQ(info.publish_unix_ns, f.info.publish_unix_ns);
  }
  cloudsvc_shm_close(c);
}

}  // namespace
}  // namespace cloudsvc
