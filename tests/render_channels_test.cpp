// Display channels (ViewRequest::channel): views of several channels drawn in turn each keep
// their own temporal history, share the frame's ground shadow map, and look as each channel
// drawn alone does; two views on one channel lose their history to each other.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/quality_presets.h"
#include "render_test_support.h"
#include "weather/presets.h"

namespace cloudsvc::test {
namespace {

ViewRequest view(double heading_deg, int channel) {
  ViewRequest v;
  v.position = {47.0, 8.0, 2500.0};
  v.attitude = {heading_deg, 4.0, 0.0};
  v.fov_deg = 50.0;
  v.width = 96;
  v.height = 54;
  v.channel = channel;
  return v;
}

double relative_difference(const FrameImage& a, const FrameImage& b) {
  double diff = 0.0, sum = 0.0;
  for (int y = 0; y < b.height; ++y)
    for (int x = 0; x < b.width; ++x) {
      diff += std::abs(luminance(a.pixel(x, y)) - luminance(b.pixel(x, y)));
      sum += luminance(b.pixel(x, y));
    }
  return diff / sum;
}

// Frames f = 0..n-1 of the views at 30 Hz, each view drawn once per frame, the first frame
// starting afresh; the last frame's images and whether every later frame used its history.
struct ChannelRun {
  std::vector<FrameImage> last;
  bool history_every_frame = true;
  bool shadow_map_shared = true;  // after the first frame (which starts afresh), no view after a frame's first rebuilt the shadow map
};

ChannelRun run_views(CloudRenderer& r, std::vector<ViewRequest> views, const RenderQuality& q, int frames = 9) {
  ChannelRun out;
  for (int f = 0; f < frames; ++f) {
    out.last.clear();
    for (std::size_t i = 0; i < views.size(); ++i) {
      ViewRequest v = views[i];
      v.unix_time_s = 1782043200.0 + f / 30.0;
      v.frame_index = static_cast<std::uint32_t>(f);
      v.reset_history = f == 0;
      const FrameImage img = r.render(v, q);
      EXPECT_EQ(count_bad_values(img), 0);
      if (f > 0) out.history_every_frame = out.history_every_frame && img.stats.history_used;
      if (f > 0 && i > 0) out.shadow_map_shared = out.shadow_map_shared && !img.stats.shadow_map_rebuilt;
      out.last.push_back(img);
    }
  }
  return out;
}

TEST(Channels, EachChannelKeepsItsHistoryAndSharesTheFrame) {
  CloudRenderer& r = shared_renderer();
  r.set_weather(*weather::preset("broken-cumulus"));
  const RenderQuality q = *quality_preset("default");
  ASSERT_GT(q.temporal_stride, 1) << "the default preset marches a part of the pixels each frame";

  // Left, centre and right windows of a cockpit, 50° apart, on channels 0, 1, 2.
  const ChannelRun three = run_views(r, {view(40.0, 0), view(90.0, 1), view(140.0, 2)}, q);
  EXPECT_TRUE(three.history_every_frame);
  EXPECT_TRUE(three.shadow_map_shared);

  // Each channel drawn alone (on a channel of its own) looks the same.
  for (int i = 0; i < 3; ++i) {
    const ChannelRun alone = run_views(r, {view(40.0 + 50.0 * i, 10 + i)}, q);
    const double d = relative_difference(three.last[static_cast<std::size_t>(i)], alone.last[0]);
    std::printf("channel %d: %.4f from the view drawn alone\n", i, d);
    EXPECT_LT(d, 0.01) << "channel " << i;
  }

  // Two of the views on one channel: each turns 50° from the other, and the history is lost.
  const ChannelRun shared = run_views(r, {view(40.0, 5), view(90.0, 5)}, q);
  EXPECT_FALSE(shared.history_every_frame);
}

}  // namespace
}  // namespace cloudsvc::test
