// Reduced numerical-stability sweep (issue "Accuracy" part 4; the full sweep is
// bench/cloudbench_stability.cpp, docs/STABILITY.md): ~200 poses over the globe at 32x18,
// 20 smoothness poses (1 cm / 0.001 deg steps) and the 30-day uptime check (GPU vs CPU
// reference, 30 days after the wind anchor).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "geodesy/solar_position.h"
#include "geodesy/utc_time.h"
#include "render_test_support.h"
#include "renderer/quality_presets.h"
#include "tests/fixtures/stability_sweep.h"

namespace cloudsvc::test {
namespace {

constexpr int kW = 32, kH = 18;  // pixels
constexpr int kFramesPerImage = 8;  // stab::SmoothLimits::frames_per_image of the per-pixel checks

TEST(StabilitySweep, NoNonFiniteNegativeOrFailedFrameAnywhere) {
  CloudRenderer& r = shared_renderer();
  const std::vector<std::string> presets = weather::preset_names();
  ASSERT_FALSE(presets.empty());
  const int per_preset = 200 / static_cast<int>(presets.size()) + 1;
  int frames = 0;
  double sun_min = 1e9, sun_max = -1e9;
  for (size_t p = 0; p < presets.size(); ++p) {
    r.set_weather(*weather::preset(presets[p]));
    for (const stab::Pose& pose : stab::make_poses(presets[p], per_preset, 4242 + p, kW, kH)) {
      const stab::FrameCheck c = stab::check_frame(r, pose.view);
      ++frames;
      sun_min = std::min(sun_min, c.sun_elevation_deg);
      sun_max = std::max(sun_max, c.sun_elevation_deg);
      EXPECT_TRUE(c.ok()) << stab::describe(pose) << ": bad values " << c.bad_values << ", nonfinite "
                          << c.nonfinite_stat << ", GL errors " << c.gl_errors << ", exception '" << c.exception << "'";
    }
  }
  EXPECT_GE(frames, 200);
  // The sweep really covers night and high sun.
  EXPECT_LT(sun_min, -15.0);
  EXPECT_GT(sun_max, 70.0);
}

// The pose generator hits the special values it promises (so the test above covers them).
TEST(StabilitySweep, PosesIncludePolesAntimeridianAndLayerBoundaries) {
  const weather::Weather wx = *weather::preset("broken-cumulus");
  ASSERT_FALSE(wx.layers.empty());
  const std::vector<stab::Pose> poses = stab::make_poses("broken-cumulus", 400, 7, kW, kH);
  int pole = 0, anti = 0, boundary = 0, vertical = 0;
  for (const stab::Pose& p : poses) {
    pole += std::abs(p.view.position.lat_deg) == 90.0;
    anti += std::abs(p.view.position.lon_deg) == 180.0;
    boundary += p.view.position.alt_m == wx.layers[0].base_m || p.view.position.alt_m == wx.layers[0].top_m;
    vertical += std::abs(p.view.attitude.pitch_deg) == 90.0;
  }
  EXPECT_GT(pole, 0);
  EXPECT_GT(anti, 0);
  EXPECT_GT(boundary, 0);
  EXPECT_GT(vertical, 0);
}

// An unreachable target gives the closest elevation of the day (the noon maximum).
TEST(StabilitySweep, SunElevationSolverHitsTarget) {
  const double day = *geo::parse_utc_iso8601("2026-03-20T00:00:00Z");
  for (double target : {-20.0, -5.0, 0.0, 30.0, 42.0}) {  // noon sun at 47.45 N on 20 March: 42.5 deg
    const double t = stab::utc_for_sun_elevation(47.45, 8.56, day, target);
    EXPECT_NEAR(geo::solar_position(t, 47.45, 8.56).elevation_deg, target, 1e-3) << target;
  }
  const double t = stab::utc_for_sun_elevation(47.45, 8.56, day, 60.0);
  EXPECT_NEAR(geo::solar_position(t, 47.45, 8.56).elevation_deg, 42.5, 0.2);
}

// The default preset's march (footprint jitter, no reuse), each image the mean of
// kFramesPerImage frames (the renderer's estimate of the pixel footprints; the step from the
// same frame indices as the base): every 1 cm / 0.001 deg pair passes the image gate, and per
// pixel no pixel changes by more than 3x its own noise (the wide floor) + 2 %.
TEST(StabilitySweep, CentimetreAndMillidegreeStepsAreSmooth) {
  CloudRenderer& r = shared_renderer();
  const std::vector<std::string> presets = weather::preset_names();
  RenderQuality q = *quality_preset("default");
  q.temporal_reuse = false;
  ASSERT_TRUE(q.footprint_jitter);
  stab::SmoothLimits lim;
  lim.frames_per_image = kFramesPerImage;
  std::string current;
  int pairs = 0, over_two_twins = 0;
  for (const stab::Pose& pose : stab::make_smooth_poses(presets, 20, 99, kW, kH)) {
    if (pose.preset != current) { r.set_weather(*weather::preset(pose.preset)); current = pose.preset; }
    for (const stab::SmoothResult& s : stab::check_smoothness(r, pose.view, lim, q)) {
      ++pairs;
      over_two_twins += s.pixels.pixels_over;
      EXPECT_TRUE(s.ok) << s.what << ": mean change " << s.step.mean_rel << " (floor " << s.jitter.mean_rel
                        << "), fraction > 1e-2 " << s.step.frac_above << " (floor " << s.jitter.frac_above
                        << "), max " << s.step.max_rel << " | " << stab::describe(pose);
      EXPECT_TRUE(s.pixels.ok_wide()) << s.what << ": " << s.pixels.pixels_over_wide << " pixels over 3 j_wide + 0.02 ("
                                      << s.pixels.wide_without_noise << " with j_wide = 0) | " << stab::describe(pose);
    }
  }
  std::printf("%d pairs; pixels over 3 j + 0.02 with two twins: %d (all within the wide floor)\n", pairs, over_two_twins);
  EXPECT_EQ(pairs, 20 * 6);
}

// The per-pixel criterion with the wide floor can fail: a 0.3-pixel pitch step of a clear
// view across the horizon (no jitter noise there: j_wide = 0) changes most pixels by more
// than 2 % (the horizon pixels and the sky and haze gradients; 448 of 576 pixels when
// written), and a 0.001 deg step of the same view passes.
TEST(StabilitySweep, PerPixelCriterionDetectsAMovedEdge) {
  CloudRenderer& r = shared_renderer();
  r.set_weather(*weather::preset("clear"));
  RenderQuality q = *quality_preset("default");
  q.temporal_reuse = false;
  const double dip_deg = std::acos(6371000.0 / 6373000.0) * 180.0 / M_PI;
  const ViewRequest v = make_view(47.45, 8.56, 2000.0, 200.0, -dip_deg, "2026-06-21T11:30:00Z", kW, kH);
  const double pixel_deg = 60.0 / kW;
  ViewRequest big = v, tiny = v;
  big.attitude.pitch_deg += 0.3 * pixel_deg;
  tiny.attitude.pitch_deg += 0.001;
  const std::vector<std::pair<std::string, ViewRequest>> steps = {{"pitch +0.3 px", big}, {"pitch +0.001 deg", tiny}};
  const std::vector<stab::SmoothResult> res = stab::check_smoothness(r, v, {}, q, {}, &steps);
  ASSERT_EQ(res.size(), 2u);
  std::printf("0.3 px: %d pixels over (wide floor; %d with j_wide = 0); 0.001 deg: %d\n", res[0].pixels.pixels_over_wide,
              res[0].pixels.wide_without_noise, res[1].pixels.pixels_over_wide);
  EXPECT_FALSE(res[0].pixels.ok_wide());
  EXPECT_GT(res[0].pixels.wide_without_noise, 0);
  EXPECT_TRUE(res[1].pixels.ok());
}

// ... and inside clouds, where the footprint jitter is noisy: cumulonimbus towers from
// 13 km, a one-pixel heading step (1.9 deg) fails the gate and, per pixel, on cloud pixels
// (j_wide > 0; 16 when written), while a 0.001 deg step passes. With single frames
// (frames_per_image 1) neither would see it: one frame's footprint noise at a cloud edge is
// the whole contrast within the pixel (0 cloud pixels over, gate passed).
TEST(StabilitySweep, PerPixelCriterionDetectsAStepInsideClouds) {
  CloudRenderer& r = shared_renderer();
  RenderQuality q = *quality_preset("default");
  q.temporal_reuse = false;
  r.set_weather(*weather::preset("cumulonimbus"));
  const ViewRequest v = make_view(47.45, 8.56, 13000.0, 200.0, -15.0, "2026-06-21T11:30:00Z", kW, kH);
  ViewRequest big = v, tiny = v;
  big.attitude.heading_deg += 60.0 / kW;
  tiny.attitude.heading_deg += 0.001;
  const std::vector<std::pair<std::string, ViewRequest>> steps = {{"heading +1 px", big}, {"heading +0.001 deg", tiny}};
  stab::SmoothLimits lim;
  lim.frames_per_image = kFramesPerImage;
  const std::vector<stab::SmoothResult> res = stab::check_smoothness(r, v, lim, q, {}, &steps);
  ASSERT_EQ(res.size(), 2u);
  const int cloud_px_over = res[0].pixels.pixels_over_wide - res[0].pixels.wide_without_noise;
  std::printf("cumulonimbus from 13 km, %d-frame means: 1 px heading: %d pixels over the wide floor (%d with j_wide > 0), gate %s; "
              "0.001 deg: %d over two twins\n", kFramesPerImage, res[0].pixels.pixels_over_wide, cloud_px_over,
              res[0].ok ? "passed" : "failed", res[1].pixels.pixels_over);
  EXPECT_GT(cloud_px_over, 0);
  EXPECT_FALSE(res[0].ok);
  EXPECT_TRUE(res[1].pixels.ok_wide());
  EXPECT_TRUE(res[1].ok);
}

// Footprint jitter (RenderQuality::footprint_jitter): each frame's ray goes through another
// point of its pixel, so a pixel whose value depends on where in the pixel it is sampled
// (a cloud top seen edge-on, an edge) shows that as frame-to-frame noise, and a 0.001 deg
// step, which moves the ray by 1/1900 of a 32x18 pixel, stays within it. Per-pixel failures
// (s > 3 j + 0.02, PixelLimits) over the ctest poses must fall, and the gate still hold.
TEST(StabilitySweep, FootprintJitterReducesPerPixelStepChanges) {
  CloudRenderer& r = shared_renderer();
  const std::vector<std::string> presets = weather::preset_names();
  RenderQuality centre, jittered;
  jittered.footprint_jitter = true;
  int over_centre = 0, over_jittered = 0, gate_jittered = 0;
  std::string current;
  for (const stab::Pose& pose : stab::make_smooth_poses(presets, 40, 7, kW, kH)) {
    if (pose.preset != current) { r.set_weather(*weather::preset(pose.preset)); current = pose.preset; }
    for (const stab::SmoothResult& s : stab::check_smoothness(r, pose.view, {}, centre))
      over_centre += s.pixels.pixels_over;
    for (const stab::SmoothResult& s : stab::check_smoothness(r, pose.view, {}, jittered)) {
      over_jittered += s.pixels.pixels_over;
      gate_jittered += s.ok ? 0 : 1;
    }
  }
  std::printf("pixels over 3 j + 0.02: centre %d, footprint jitter %d; gate failures with jitter %d\n", over_centre,
              over_jittered, gate_jittered);
  EXPECT_EQ(gate_jittered, 0);
  EXPECT_LT(over_jittered, over_centre);
}

// A perturbation far larger than 1 cm must fail the same criterion: the check can fail.
TEST(StabilitySweep, SmoothnessCriterionDetectsARealChange) {
  CloudRenderer& r = shared_renderer();
  r.set_weather(*weather::preset("broken-cumulus"));
  ViewRequest v = make_view(47.45, 8.56, 800.0, 250.0, 8.0, "2026-06-21T11:30:00Z", kW, kH);
  FrameImage a, b, jit1, jit2;
  ASSERT_TRUE(stab::check_frame(r, v, &a).ok());
  ViewRequest vj1 = v, vj2 = v;
  vj1.frame_index += 1;
  vj2.frame_index += 2;
  ASSERT_TRUE(stab::check_frame(r, vj1, &jit1).ok());
  ASSERT_TRUE(stab::check_frame(r, vj2, &jit2).ok());
  ViewRequest moved = v;
  moved.attitude.heading_deg += 5.0;  // 2.6 pixels
  ASSERT_TRUE(stab::check_frame(r, moved, &b).ok());
  const stab::SmoothLimits lim;
  const stab::ImageDiff step = stab::image_diff(a, b, lim.tau);
  const stab::ImageDiff floor = stab::jitter_floor(stab::image_diff(a, jit1, lim.tau), stab::image_diff(a, jit2, lim.tau));
  EXPECT_FALSE(stab::smooth_step_ok(step, floor, lim));
  EXPECT_GT(step.mean_rel, std::max(lim.noise_spread * floor.mean_rel, lim.min_mean));  // on the mean alone too
}

// The real uptime case: weather set (wind anchor latched) at T, then the same view
// rendered at T + 600/1200/1800 s, T + 1 h and T + 30 d (+ 0/600/1200 s) with no
// re-anchoring, each compared with the CPU reference for the same anchor and time, and the
// GPU's float noise coordinates compared with double (stab::check_uptime). Below every
// layer, looking at the cloud bases (so every case has clouds in view), 32x18.
TEST(StabilitySweep, ThirtyDaysAfterTheWindAnchorMatchTheReference) {
  CloudRenderer& r = shared_renderer();
  const ViewRequest v = make_view(47.45, 8.56, 300.0, 250.0, 10.0, "2026-06-06T10:00:00Z", kW, kH);
  const stab::UptimeLimits lim;
  for (const char* name : {"broken-cumulus", "scattered-cumulus"}) {
    const stab::UptimeResult u = stab::check_uptime(r, *weather::preset(name), v, lim);
    ASSERT_EQ(u.cases.size(), 7u);
    for (const stab::UptimeCase& c : u.cases) {
      std::printf("%-17s group %d elapsed %9.0f s: PSNR %.2f dB (rel RMSE %.3f), ref clouds %.2f, "
                  "noise coord err %.3g m (ratio %.3f)\n",
                  name, c.group, c.elapsed_s, c.psnr_db, c.relative_rmse, c.ref_cloud_fraction, c.coord_err_m,
                  c.coord_err_ratio);
      EXPECT_LE(c.coord_err_ratio, 1.0) << name << " after " << c.elapsed_s << " s: " << c.coord_err_m << " m";
      EXPECT_GT(c.ref_cloud_fraction, 0.3) << name << " after " << c.elapsed_s << " s: clouds in view";
      if (c.group != 0) {
        EXPECT_GE(c.psnr_db, u.min_psnr[0] - lim.psnr_margin_db) << name << " after " << c.elapsed_s << " s";
      }
    }
    EXPECT_GE(u.mean_psnr[2], u.mean_psnr[0] - lim.psnr_margin_db) << name;
    EXPECT_GT(u.drift_mean_rel, 0.05) << name << ": the clouds must move between 600 s and 1 h";
    EXPECT_TRUE(u.ok()) << name;
  }
}

}  // namespace
}  // namespace cloudsvc::test
