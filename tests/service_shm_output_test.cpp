// The shared-memory output of `cloudsvc serve` end to end: SetView picks the ring's pixel
// format (RGBA8 sRGB tone-mapped or RGBA16F linear) and the slot header describes the frame
// (format, row and pixel bytes) with plausible pixels; the slot carries the time the writer
// published it.
#include <gtest/gtest.h>

#include <algorithm>
#include <ctime>

#include "service_test_support.h"
#include "shm_frame_stats.h"
#include "sim_client/service_connection.h"

namespace cloudsvc::test {
namespace {

using namespace std::chrono_literals;
using client::ServiceConnection;

// The test pose, 5 deg up, with no history (each frame on its own).
protocol::Pose day_pose(double lat) {
  protocol::Pose p = test_pose(lat);
  p.pitch_deg = 5.0;
  p.flags = protocol::pose_flag::kTeleport;
  return p;
}

protocol::SetView shm_view(protocol::ShmPixelFormat format) {
  protocol::SetView v;
  v.width = 64;
  v.height = 36;
  v.hfov_deg = 60.0;
  v.sinks = protocol::sink::kShm;
  v.shm_format = format;
  return v;
}

std::int64_t realtime_ns() {
  timespec ts{};
  ::clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

// Renders a pose and reads its frame; the slot's publish time lies between sending the
// pose and receiving FrameReady (the service publishes before announcing).
ShmFrame render(ServiceConnection& c, const ServiceProcess& svc, double lat) {
  const std::int64_t sent = realtime_ns();
  c.send(day_pose(lat));
  const auto ready = c.receive_until<protocol::FrameReady>(60s);
  const std::int64_t received = realtime_ns();
  EXPECT_TRUE(ready.shm_slot.has_value());
  ShmFrame f;
  EXPECT_TRUE(read_frame(svc.shm_name(), ready.frame_number, f));
  EXPECT_EQ(f.info.lat_deg, lat);
  EXPECT_GT(f.info.publish_unix_ns, sent);
  EXPECT_LT(f.info.publish_unix_ns, received);
  return f;
}

TEST(ServiceShmOutput, SetViewChoosesRgba8SrgbAndBackToRgba16f) {
  ServiceProcess svc("shm_rgba8");
  ASSERT_TRUE(svc.running());
  ServiceConnection c(svc.address(), "rgba8");
  c.send(shm_view(protocol::ShmPixelFormat::Rgba8Srgb));
  const ShmFrame f = render(c, svc, 47.45);
  EXPECT_EQ(f.info.pixel_format, CLOUDSVC_SHM_RGBA8_SRGB);
  EXPECT_EQ(f.info.width, 64u);
  EXPECT_EQ(f.info.height, 36u);
  EXPECT_EQ(f.info.row_bytes, 64u * 4u);
  EXPECT_EQ(f.info.pixel_bytes, 64u * 36u * 4u);
  ASSERT_EQ(f.pixels.size(), 64u * 36u * 4u);
  // Display pixels of a daytime view 5 deg above the horizon: opaque (A = 255), neither
  // black nor blown out, varied, and the top row (sky) bluer than red.
  double sum = 0.0, top_r = 0.0, top_b = 0.0;
  std::uint8_t lo = 255, hi = 0;
  for (std::size_t i = 0; i < 64u * 36u; ++i) {
    const std::uint8_t* px = f.pixels.data() + 4 * i;
    ASSERT_EQ(px[3], 255) << "pixel " << i;
    for (int k = 0; k < 3; ++k) {
      sum += px[k];
      lo = std::min(lo, px[k]);
      hi = std::max(hi, px[k]);
    }
    if (i < 64) {
      top_r += px[0];
      top_b += px[2];
    }
  }
  const double mean = sum / (64.0 * 36.0 * 3.0);  // 0..255
  RecordProperty("rgba8_mean", std::to_string(mean));
  EXPECT_GT(mean, 20.0);
  EXPECT_LT(mean, 235.0);
  EXPECT_GT(hi - lo, 30) << "a flat image";
  EXPECT_GT(top_b, top_r) << "the sky is not blue";

  c.send(shm_view(protocol::ShmPixelFormat::Rgba16fLinear));
  const ShmFrame g = render(c, svc, 47.46);
  EXPECT_EQ(g.info.pixel_format, CLOUDSVC_SHM_RGBA16F_LINEAR);
  EXPECT_EQ(g.info.row_bytes, 64u * 8u);
  EXPECT_EQ(g.info.pixel_bytes, 64u * 36u * 8u);
  const FrameStats s = stats_of(g);
  EXPECT_EQ(s.nonfinite, 0u);
  EXPECT_GT(s.mean_luminance, 0.0);
  EXPECT_EQ(svc.stop(), 0);
}

}  // namespace
}  // namespace cloudsvc::test
