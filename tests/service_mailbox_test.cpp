// The bounds of the FrameMailbox (service/frame_mailbox.h) that keep one client from
// queueing unbounded work: render requests per client, the byte budget of weather tiles
// waiting to be applied, and one request per client per batch so no client's requests
// hold back another's.
#include <gtest/gtest.h>

#include "service/frame_mailbox.h"

namespace cloudsvc {
namespace {

using namespace std::chrono_literals;

protocol::WeatherMapTile tile_of(std::uint32_t side) {
  protocol::WeatherMapTile t;
  t.lat_min_deg = 0, t.lat_max_deg = 1, t.lon_min_deg = 0, t.lon_max_deg = 1;
  t.width = t.height = side;
  t.channels = 1;
  t.data.assign(static_cast<std::size_t>(side) * side, 0.5f);
  return t;
}

TEST(FrameMailbox, RenderRequestsAreBoundedPerClient) {
  FrameMailbox mb;
  const std::size_t limit = FrameMailbox::kMaxRendersPerClient;
  for (std::size_t i = 0; i < limit; ++i) EXPECT_TRUE(mb.post_render({i + 1, 7, {}}));
  EXPECT_FALSE(mb.post_render({99, 7, {}})) << "a third request of client 7 is refused, not queued";
  EXPECT_TRUE(mb.post_render({1, 8, {}})) << "another client is not affected";
  // One request per client per batch, oldest first.
  MailboxBatch b = mb.take(0ms);
  ASSERT_EQ(b.renders.size(), 2u);
  EXPECT_EQ(b.renders[0].client_id, 7u);
  EXPECT_EQ(b.renders[0].request_id, 1u);
  EXPECT_EQ(b.renders[1].client_id, 8u);
  EXPECT_FALSE(mb.post_render({100, 7, {}})) << "taken but not finished still counts";
  mb.render_finished(7);
  EXPECT_TRUE(mb.post_render({101, 7, {}})) << "a finished request frees its place";
  b = mb.take(0ms);
  ASSERT_EQ(b.renders.size(), 1u);
  EXPECT_EQ(b.renders[0].request_id, 2u) << "the older request of client 7 comes next";
}

TEST(FrameMailbox, WeatherTilesStayWithinTheByteBudget) {
  const protocol::WeatherMapTile big = tile_of(512);  // 1 MiB of values
  const std::size_t bytes = FrameMailbox::tile_bytes(big);
  ASSERT_EQ(bytes, std::size_t{512} * 512 * 4);
  FrameMailbox mb(3 * bytes);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(mb.post_change(big));
  EXPECT_FALSE(mb.post_change(big)) << "the fourth tile would exceed the budget";
  EXPECT_TRUE(mb.post_change(protocol::SetTime{1.0})) << "other changes are never refused";
  MailboxBatch b = mb.take(0ms);
  ASSERT_EQ(b.changes.size(), 4u) << "everything accepted is delivered, in order";
  EXPECT_FALSE(mb.post_change(big)) << "taken but not yet applied still counts";
  mb.tile_applied(std::get<protocol::WeatherMapTile>(b.changes[0]));
  EXPECT_TRUE(mb.post_change(big)) << "an applied tile frees its bytes";
}

TEST(FrameMailbox, StopIsStickyAndPosesAreLatestWins) {
  FrameMailbox mb;
  PendingPose a, c;
  a.pose.sim_time_s = 1.0;
  a.pose.flags = protocol::pose_flag::kAll;
  c.pose.sim_time_s = 2.0;
  mb.post_pose(a);
  mb.post_pose(c);
  MailboxBatch b = mb.take(0ms);
  ASSERT_TRUE(b.pose.has_value());
  EXPECT_EQ(b.pose->pose.sim_time_s, 2.0);
  EXPECT_EQ(b.pose->pose.flags, protocol::pose_flag::kAll) << "a dropped pose's reset flag carries over";
  EXPECT_EQ(mb.poses_dropped(), 1u);
  mb.request_stop();
  EXPECT_TRUE(mb.take(0ms).stop);
  EXPECT_TRUE(mb.take(0ms).stop);
}

}  // namespace
}  // namespace cloudsvc
