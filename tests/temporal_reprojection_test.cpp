// The CPU side of temporal reuse (renderer/temporal_reprojection.h): the transforms carry a
// point seen from the current camera to where the previous camera saw the same material,
// the dither order covers every pixel, and the history is dropped when it must be.
#include <gtest/gtest.h>

#include <set>

#include "geodesy/geodetic.h"
#include "renderer/temporal_reprojection.h"
#include "weather/wind_drift.h"

namespace cloudsvc {
namespace {

// make_reprojection and cloud_motion_px of the two views' frame contexts, built as
// CloudRenderer builds them (one wind anchor).
Reprojection reprojection_of(const ViewRequest& prev, const ViewRequest& cur, const weather::Weather& w,
                             const WindAnchor& anchor) {
  return make_reprojection(make_frame_context(prev, w, anchor), make_frame_context(cur, w, anchor));
}
double motion_px(const ViewRequest& prev, const ViewRequest& cur, const weather::Weather& w) {
  const WindAnchor anchor{prev.position, prev.unix_time_s};
  return cloud_motion_px(make_frame_context(prev, w, anchor), make_frame_context(cur, w, anchor));
}

ViewRequest view_at(double lat, double lon, double alt, double heading, double pitch, double roll, double t) {
  ViewRequest v;
  v.position = {lat, lon, alt};
  v.attitude = {heading, pitch, roll};
  v.unix_time_s = t;
  v.width = 160;
  v.height = 90;
  return v;
}

// ECEF of a point given in a view's local ENU frame.
glm::dvec3 to_ecef(const ViewRequest& v, const glm::dvec3& local) {
  return geo::geodetic_to_ecef(v.position) + geo::enu_to_ecef(v.position.lat_deg, v.position.lon_deg) * local;
}

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

TEST(TemporalReprojection, GroundTransformMapsTheSameWorldPointBetweenCameras) {
  const ViewRequest prev = view_at(47.45, 8.56, 1800.0, 250.0, 3.0, 1.0, 1000.0);
  const ViewRequest cur = view_at(47.4503, 8.5592, 1795.0, 250.1, 3.0, 1.5, 1000.0 + 1.0 / 30.0);
  const Reprojection r = reprojection_of(prev, cur, weather::Weather{}, WindAnchor{prev.position, prev.unix_time_s});
  for (const glm::dvec3 p : {glm::dvec3(100.0, 2000.0, -50.0), glm::dvec3(-30000.0, 80000.0, 1500.0)}) {
    const glm::dvec3 world = to_ecef(cur, p);
    const glm::dvec3 expected = glm::transpose(geo::enu_to_ecef(prev.position.lat_deg, prev.position.lon_deg)) *
                                (world - geo::geodetic_to_ecef(prev.position));
    const glm::dvec3 got = apply(r.transform[kGroundTransform], p);
    EXPECT_LT(glm::length(got - expected), 1e-6) << p.x;
  }
  EXPECT_NEAR(glm::length(r.prev_axes.forward - geo::body_axes_enu(prev.attitude).forward), 0.0, 1e-15);
}

TEST(TemporalReprojection, LayerTransformFollowsTheWind) {
  weather::Weather w;
  weather::CloudLayer l;
  l.wind = {30.0, -10.0};
  w.layers.push_back(l);
  const ViewRequest prev = view_at(47.45, 8.56, 1000.0, 0.0, 0.0, 0.0, 5000.0);
  const ViewRequest cur = view_at(47.45, 8.56, 1000.0, 0.0, 0.0, 0.0, 5002.0);  // 2 s later, same camera
  const WindAnchor anchor{prev.position, 4000.0};
  const Reprojection r = reprojection_of(prev, cur, w, anchor);
  // Material now 5 km north of the camera sat 2 s of wind upwind: (-60, +20) m in ENU.
  const glm::dvec3 p(0.0, 5000.0, 500.0);
  const glm::dvec3 was = apply(r.transform[0], p);
  EXPECT_NEAR(was.x - p.x, -60.0, 0.05);
  EXPECT_NEAR(was.y - p.y, 20.0, 0.05);
  EXPECT_NEAR(was.z - p.z, 0.0, 0.2);  // the field turns about the centre of the Earth
  // The density field agrees: sampling it at the earlier time at `was` equals now at p.
  const glm::dmat3 rot_prev = wind_rotation(l.wind, anchor, prev.unix_time_s);
  const glm::dmat3 rot_cur = wind_rotation(l.wind, anchor, cur.unix_time_s);
  const glm::dvec3 field_then = rot_prev * to_ecef(prev, was), field_now = rot_cur * to_ecef(cur, p);
  EXPECT_LT(glm::length(field_then - field_now), 1e-6);
  // the ground does not move
  EXPECT_LT(glm::length(apply(r.transform[kGroundTransform], p) - p), 1e-6);
}

TEST(TemporalReprojection, DitherOrderVisitsEveryPixelOncePerCycle) {
  for (int stride : {2, 4}) {
    std::set<std::pair<int, int>> seen;
    for (std::uint32_t f = 0; f < static_cast<std::uint32_t>(stride * stride); ++f) {
      const glm::ivec2 o = fresh_pixel_offset(stride, f + 1000u * static_cast<std::uint32_t>(stride * stride));
      EXPECT_TRUE(o.x >= 0 && o.x < stride && o.y >= 0 && o.y < stride);
      seen.insert({o.x, o.y});
    }
    EXPECT_EQ(seen.size(), static_cast<size_t>(stride * stride));
  }
  EXPECT_EQ(fresh_pixel_offset(1, 7), glm::ivec2(0, 0));
}

TEST(TemporalReprojection, HistoryRules) {
  const ViewRequest a = view_at(47.45, 8.56, 1000.0, 0.0, 0.0, 0.0, 100.0);
  RenderQuality q;
  q.temporal_reuse = true;
  q.temporal_stride = 4;
  ViewRequest b = a;
  b.unix_time_s += 1.0 / 30.0;
  b.position.lat_deg += 0.0001;  // 11 m
  EXPECT_TRUE(history_usable(a, q, b, q));
  ViewRequest t = b;
  t.reset_history = true;
  EXPECT_FALSE(history_usable(a, q, t, q));
  ViewRequest far = b;
  far.position.lat_deg += 0.05;  // 5.6 km
  EXPECT_FALSE(history_usable(a, q, far, q));
  ViewRequest late = b;
  late.unix_time_s = a.unix_time_s + 0.6;  // a slide show: each frame stands alone
  EXPECT_FALSE(history_usable(a, q, late, q));
  late.unix_time_s = a.unix_time_s + 0.4;
  EXPECT_TRUE(history_usable(a, q, late, q));
  ViewRequest snap = b;
  snap.attitude.heading_deg += 12.0;  // a snap turn
  EXPECT_FALSE(history_usable(a, q, snap, q));
  snap.attitude.heading_deg -= 4.0;   // 8 deg in a frame: still reused
  EXPECT_TRUE(history_usable(a, q, snap, q));
  ViewRequest earlier = b;
  earlier.unix_time_s = a.unix_time_s - 0.01;
  EXPECT_FALSE(history_usable(a, q, earlier, q));
  RenderQuality q2 = q;
  q2.primary_steps = 32;
  EXPECT_FALSE(history_usable(a, q, b, q2));
  ViewRequest zoom = b;
  zoom.fov_deg = 30.0;
  EXPECT_FALSE(history_usable(a, q, zoom, q));
  RenderQuality off = q;
  off.temporal_reuse = false;
  EXPECT_FALSE(history_usable(a, off, b, off));
  EXPECT_TRUE(camera_still(a, a));
  EXPECT_FALSE(camera_still(a, b));
}

// Footprint samples: the centre while nothing accumulates; in a still run at 1/16 px per
// frame, every pixel's second sample (frames 1-16 of the run) is its first jitter point, the
// third (frames 17-32) its second; at 1/4 px per frame one per 4 frames; a full march
// (stride 1) takes a new point every still frame.
TEST(TemporalReprojection, FootprintSampleStartsAtThePixelCentre) {
  EXPECT_EQ(footprint_sample_index(0, 4), 0);
  EXPECT_EQ(footprint_sample_index(-1, 4), 0);
  for (int s = 1; s <= 16; ++s) EXPECT_EQ(footprint_sample_index(s, 4), 1) << s;
  for (int s = 17; s <= 32; ++s) EXPECT_EQ(footprint_sample_index(s, 4), 2) << s;
  EXPECT_EQ(footprint_sample_index(4, 2), 1);
  EXPECT_EQ(footprint_sample_index(5, 2), 2);
  EXPECT_EQ(footprint_sample_index(3, 1), 3);
  EXPECT_EQ(footprint_sample_index(3, 0), 3);  // stride 0 is read as 1
  // without temporal reuse the frame index picks the point (a caller's own accumulation)
  EXPECT_EQ(footprint_sample_index(false, 0u, 0, 1), 0);
  EXPECT_EQ(footprint_sample_index(false, 7u, 0, 1), 7);
  EXPECT_EQ(footprint_sample_index(false, 65536u + 3u, 5, 4), 3);
  EXPECT_EQ(footprint_sample_index(true, 7u, 0, 4), 0);
  EXPECT_EQ(footprint_sample_index(true, 7u, 17, 4), 2);
}

// The image motion of the nearest clouds per frame, and the default preset marching 1/4
// instead of 1/16 of the pixels while it exceeds a pixel.
TEST(TemporalReprojection, FastCloseMotionMarchesMorePixels) {
  weather::Weather w;
  weather::CloudLayer l;
  l.base_m = 1000.0;
  l.top_m = 2000.0;
  w.layers.push_back(l);
  const double pixel_rad = 60.0 * M_PI / 180.0 / 160.0;  // view_at: 160 px, 60 deg
  const ViewRequest a = view_at(47.45, 8.56, 2500.0, 90.0, 0.0, 0.0, 100.0);
  EXPECT_EQ(motion_px(a, a, w), 0.0);
  ViewRequest turned = a;
  turned.attitude.heading_deg += 1.0;
  EXPECT_NEAR(motion_px(a, turned, w), (M_PI / 180.0) / pixel_rad, 1e-6);
  turned.attitude.roll_deg += 2.0;  // the up axis turns by 2 deg about forward
  EXPECT_NEAR(motion_px(a, turned, w), 2.0 * (M_PI / 180.0) / pixel_rad, 0.01);
  // 250 m/s at 30 frames/s, 500 m above the layer top
  const glm::dvec3 step = geo::enu_to_ecef(a.position.lat_deg, a.position.lon_deg) * glm::dvec3(250.0 / 30.0, 0.0, 0.0);
  ViewRequest flown = a;
  flown.position = geo::ecef_to_geodetic(geo::geodetic_to_ecef(a.position) + step);
  flown.unix_time_s += 1.0 / 30.0;
  EXPECT_NEAR(motion_px(a, flown, w), std::atan(250.0 / 30.0 / 500.0) / pixel_rad, 0.01);
  // the same speed at 10 km: slow across the image
  ViewRequest high_a = a, high_b = flown;
  high_a.position.alt_m = high_b.position.alt_m = 10000.0;
  EXPECT_LT(motion_px(high_a, high_b, w), 0.2);
  // inside the layer: clouds may be metres away
  ViewRequest in_a = a, in_b = flown;
  in_a.position.alt_m = in_b.position.alt_m = 1500.0;
  EXPECT_GT(motion_px(in_a, in_b, w), 100.0);
  EXPECT_EQ(motion_px(a, flown, weather::Weather{}), 0.0);  // no clouds, nothing moves

  RenderQuality q;
  q.temporal_reuse = true;
  q.temporal_stride = 4;
  q.fast_motion_px = 1.0;
  const WindAnchor anchor{a.position, a.unix_time_s};
  const Reprojection fast = reprojection_of(a, flown, w, anchor);
  EXPECT_TRUE(fast_cloud_motion(fast, q));
  EXPECT_EQ(plan_temporal_frame(flown, q, true, &a, true).stride, 2);
  const Reprojection slow = reprojection_of(high_a, high_b, w, anchor);
  EXPECT_FALSE(fast_cloud_motion(slow, q));
  EXPECT_EQ(plan_temporal_frame(high_b, q, true, &high_a, false).stride, 4);
  EXPECT_EQ(plan_temporal_frame(flown, q, false, nullptr, true).stride, 1);  // no history: all
  q.fast_motion_px = 0.0;  // off
  EXPECT_FALSE(fast_cloud_motion(fast, q));
}

// Motion hovering at the threshold must not alternate the two dither orders (which would
// leave pixel rows never marched): after a fast frame the 1/4 stride holds for a cycle.
TEST(TemporalReprojection, FastMotionHoldsForAWholeCycle) {
  FastMotionHold hold;
  for (int i = 0; i < 20; ++i) EXPECT_TRUE(hold.update(i % 2 == 0, true)) << i;  // alternating: held
  EXPECT_TRUE(hold.update(true, true));
  for (int i = 1; i < kFastMotionHoldFrames; ++i) EXPECT_TRUE(hold.update(false, true)) << i;
  EXPECT_FALSE(hold.update(false, true));
  EXPECT_TRUE(hold.update(true, true));
  EXPECT_FALSE(hold.update(false, false));  // a teleport ends it
  EXPECT_FALSE(hold.update(false, true));

  // With the hold, alternating fast/slow frames march every cloud pixel within 8 frames.
  std::set<std::pair<int, int>> marched;
  FastMotionHold h2;
  for (std::uint32_t f = 0; f < 8; ++f) {
    const int stride = h2.update(f % 2 == 0, true) ? 2 : 4;
    const glm::ivec2 o = fresh_pixel_offset(stride, f);
    for (int y = o.y; y < 8; y += stride)
      for (int x = o.x; x < 8; x += stride) marched.insert({x, y});
  }
  EXPECT_EQ(marched.size(), 64u);
}

}  // namespace
}  // namespace cloudsvc
