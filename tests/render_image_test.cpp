// Image facts of the GPU renderer (issue: renderer core). Small images on llvmpipe.
// Each test checks a physical fact a user would notice if it were wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <string>
#include <vector>

#include "geodesy/shell_intersection.h"
#include "geodesy/solar_position.h"
#include <epoxy/gl.h>

#include "render_test_support.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/reference_renderer.h"

namespace cloudsvc::test {
namespace {

constexpr double kDeg = M_PI / 180.0;
const char* kNoonZurich = "2026-06-21T11:30:00Z";

TEST(RenderImage, NoNonFiniteOrNegativePixelsInAnyPresetOrView) {
  struct Pose { double alt, pitch; const char* time; };
  const std::vector<Pose> poses = {
      {2.0, 10.0, kNoonZurich},      // on the ground, looking up
      {1500.0, 0.0, kNoonZurich},    // inside most low layers
      {4000.0, -30.0, kNoonZurich},  // above low layers
      {30000.0, -25.0, kNoonZurich}, // stratosphere
      {100000.0, -60.0, kNoonZurich},  // top of the atmosphere
      {800.0, 5.0, "2026-06-21T19:20:00Z"},  // sunset
      {800.0, 5.0, "2026-06-21T23:00:00Z"},  // night
  };
  for (const std::string& name : weather::preset_names()) {
    for (const Pose& p : poses) {
      const FrameImage img = render_preset(name, make_view(47.45, 8.56, p.alt, 250.0, p.pitch, p.time, 96, 54));
      EXPECT_EQ(count_bad_values(img), 0) << name << " alt " << p.alt << " " << p.time;
      EXPECT_EQ(img.stats.nonfinite_pixels, 0) << name << " alt " << p.alt << " " << p.time;
    }
  }
}

// Rayleigh scattering: the clear noon sky is bluer (higher blue/red ratio) at the zenith
// than near the horizon, where the long path reddens and whitens it.
// Mesa's llvmpipe ends every loop of a shader invocation once its loops have run 65535
// iterations in all (docs/RENDERING.md "Output"). A level march of 4096 primary x 32 light
// steps through a thin stratus deck needs ~135 000 and must be reported as cut short; the
// default preset's march of the same view must not be (nor, on a driver without the cap,
// the long one).
TEST(RenderImage, RaysTheDriverCutsShortAreCounted) {
  weather::Weather w = single_layer(weather::CloudType::Stratus, 500.0, 1500.0, 1.0);
  w.layers[0].density_scale = 0.001;  // optical depth ~4 over the deck's 80 km: no early exit
  CloudRenderer& r = shared_renderer();
  r.set_weather(w);
  const ViewRequest v = make_view(47.45, 8.56, 1000.0, 90.0, 0.0, kNoonZurich, 16, 9);
  RenderQuality heavy;
  heavy.primary_steps = 4096;
  heavy.light_steps = 32;
  heavy.temporal_reuse = false;
  const FrameImage capped = r.render(v, heavy);
  const FrameImage normal = r.render(v, *quality_preset("default"));
  EXPECT_EQ(normal.stats.loop_capped_invocations, 0);
  const std::string gl_renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  std::printf("%s: %lld of %d invocations cut short at 4096 x 32 steps\n", gl_renderer.c_str(),
              static_cast<long long>(capped.stats.loop_capped_invocations), v.width * v.height);
  if (gl_renderer.find("llvmpipe") != std::string::npos)
    EXPECT_GT(capped.stats.loop_capped_invocations, 0);
  else
    EXPECT_EQ(capped.stats.loop_capped_invocations, 0);
}

TEST(RenderImage, ClearSkyZenithBluerThanHorizon) {
  const FrameImage up = render_preset("clear", make_view(47.45, 8.56, 10.0, 0.0, 90.0, kNoonZurich, 32, 32, 10.0));
  const FrameImage horizon = render_preset("clear", make_view(47.45, 8.56, 10.0, 0.0, 2.0, kNoonZurich, 32, 32, 2.0));
  const float* z = up.pixel(16, 16);
  const float* hz = horizon.pixel(16, 8);  // slightly above the horizon
  const double zenith_blueness = z[2] / z[0];
  const double horizon_blueness = hz[2] / hz[0];
  EXPECT_GT(zenith_blueness, 1.5) << "zenith sky should be clearly blue";
  EXPECT_GT(zenith_blueness, 1.3 * horizon_blueness);
}

TEST(RenderImage, NightIsOrdersOfMagnitudeDarkerThanDay) {
  const FrameImage day = render_preset("scattered-cumulus", make_view(47.45, 8.56, 500.0, 0.0, 10.0, kNoonZurich));
  const FrameImage night =
      render_preset("scattered-cumulus", make_view(47.45, 8.56, 500.0, 0.0, 10.0, "2026-06-21T23:30:00Z"));
  EXPECT_LT(night.stats.sun_elevation_deg, -12.0);
  EXPECT_GT(mean_luminance(day), 1000.0 * mean_luminance(night));
}

// Ground seen from 150 m, looking down, under an overcast deck vs a clear sky.
TEST(RenderImage, GroundUnderOvercastIsDarkerThanUnderClearSky) {
  const ViewRequest v = make_view(47.45, 8.56, 150.0, 90.0, -45.0, kNoonZurich);
  const FrameImage clear = render_preset("clear", v);
  const FrameImage overcast = render_preset("overcast-stratus", v);
  const double lc = mean_luminance(clear), lo = mean_luminance(overcast);
  EXPECT_LT(lo, 0.5 * lc) << "clear " << lc << " overcast " << lo;
  EXPECT_GT(lo, 0.0);
}

// Seen from above, a sunlit deck is brighter than the ground seen through its gaps.
TEST(RenderImage, DeckSeenFromAboveIsBrighterThanGroundInGaps) {
  const FrameImage img = render_weather(single_layer(weather::CloudType::Stratocumulus, 1200, 1800, 0.6),
                                        make_view(47.45, 8.56, 3500.0, 90.0, -60.0, kNoonZurich, 160, 90));
  double deck = 0.0, gap = 0.0;
  int nd = 0, ng = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const float a = img.pixel(x, y)[3];
      if (a > 0.95f) { deck += luminance(img.pixel(x, y)); ++nd; }
      if (a < 0.05f) { gap += luminance(img.pixel(x, y)); ++ng; }
    }
  ASSERT_GT(nd, 100) << "expected deck pixels";
  ASSERT_GT(ng, 20) << "expected gaps in a stratocumulus deck";
  EXPECT_GT(deck / nd, 2.0 * gap / ng);
}

// Cloud shadows fall where the sun direction says: for ground pixels seen through gaps,
// follow the sun direction up to the layer's middle and project that point back into the
// image. Where the image shows cloud there, the ground must be in shadow (darker).
TEST(RenderImage, CloudShadowsFallAlongTheSunDirection) {
  const ViewRequest v = make_view(47.45, 8.56, 6000.0, 90.0, -75.0, "2026-06-21T08:00:00Z", 200, 200, 80.0);
  const weather::Weather w = single_layer(weather::CloudType::Stratocumulus, 1200, 1800, 0.45);
  const FrameImage img = render_weather(w, v);
  const double mid = 0.5 * (w.layers[0].base_m + w.layers[0].top_m);

  const geo::BodyAxes ax = geo::body_axes_enu(v.attitude);
  const double R = geo::gaussian_radius(v.position.lat_deg), h = v.position.alt_m;
  const double tan_h = std::tan(0.5 * v.fov_deg * kDeg), tan_v = tan_h * v.height / v.width;
  const geo::SolarPosition sp = geo::solar_position(v.unix_time_s, v.position.lat_deg, v.position.lon_deg);
  auto sun_enu = [&](double az_deg) {
    const double el = sp.elevation_deg * kDeg, az = az_deg * kDeg;
    return glm::dvec3(std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el));
  };
  // Mean ground luminance where the projected caster is cloud vs clear, for a sun azimuth.
  auto shadow_contrast = [&](glm::dvec3 sun) {
    double lit = 0, shade = 0;
    int n_lit = 0, n_shade = 0;
    for (int y = 0; y < v.height; ++y)
      for (int x = 0; x < v.width; ++x) {
        if (img.pixel(x, y)[3] > 0.02f) continue;  // cloud in front of the ground
        const double nx = ((x + 0.5) / v.width) * 2 - 1, ny = -(((y + 0.5) / v.height) * 2 - 1);
        const glm::dvec3 d = glm::normalize(ax.forward + nx * tan_h * ax.right + ny * tan_v * ax.up);
        const auto g = geo::intersect_shell<double>(R, h, 0.0, d.z);
        if (g.count < 2) continue;
        const glm::dvec3 p = g.t_near * d;
        const glm::dvec3 up = glm::normalize(p + glm::dvec3(0, 0, R + h));
        const auto s = geo::intersect_shell<double>(R, 0.0, mid, glm::dot(up, sun));
        const glm::dvec3 q = p + s.t_near * sun;  // caster point at mid-layer
        const double f = glm::dot(q, ax.forward);
        if (f <= 0) continue;
        const int qx = static_cast<int>(std::floor(((glm::dot(q, ax.right) / f / tan_h) + 1) * 0.5 * v.width));
        const int qy = static_cast<int>(std::floor((1 - glm::dot(q, ax.up) / f / tan_v) * 0.5 * v.height));
        if (qx < 0 || qy < 0 || qx >= v.width || qy >= v.height) continue;
        const float a = img.pixel(qx, qy)[3];
        const double l = luminance(img.pixel(x, y));
        if (a > 0.9f) { shade += l; ++n_shade; }
        if (a < 0.05f) { lit += l; ++n_lit; }
      }
    EXPECT_GT(n_shade, 30);
    EXPECT_GT(n_lit, 30);
    return (shade / std::max(n_shade, 1)) / (lit / std::max(n_lit, 1));
  };
  ASSERT_GT(sp.elevation_deg, 30.0);
  const double true_ratio = shadow_contrast(sun_enu(sp.azimuth_deg));
  const double wrong_ratio = shadow_contrast(sun_enu(sp.azimuth_deg + 180.0));
  std::printf("shadowed/lit ground luminance: %.3f (true sun), %.3f (mirrored sun)\n", true_ratio, wrong_ratio);
  // Shadowed ground still gets sky light and light diffused through the cloud, and the
  // caster classification is approximate (the camera sees columns, not the mid-layer
  // point), so the ratio is well above 0; a real shadow still makes it clearly below 1.
  EXPECT_LT(true_ratio, 0.65) << "ground under predicted cloud shadow should be much darker";
  EXPECT_GT(wrong_ratio, 1.5 * true_ratio) << "a mirrored sun must not explain the shadows as well";
}

// Crossing the antimeridian changes nothing: 0.0002 deg of longitude apart (~11 m at
// 60 N), the two images agree to a few percent.
TEST(RenderImage, AntimeridianViewsMatch) {
  const FrameImage a = render_preset("broken-cumulus", make_view(60.0, 179.9999, 1500.0, 90.0, 0.0, "2026-06-21T00:30:00Z"));
  const FrameImage b = render_preset("broken-cumulus", make_view(60.0, -179.9999, 1500.0, 90.0, 0.0, "2026-06-21T00:30:00Z"));
  double diff = 0.0, sum = 0.0;
  for (size_t i = 0; i < a.rgba.size(); i += 4)
    for (int c = 0; c < 3; ++c) { diff += std::abs(a.rgba[i + c] - b.rgba[i + c]); sum += a.rgba[i + c]; }
  EXPECT_GT(a.stats.cloud_pixels, 100);
  EXPECT_LT(diff / sum, 0.05);
}

// Exactly at the poles the image is clean, and two cameras 2.2 m apart on opposite sides
// of the north pole, looking along the same ECEF direction (north at lon 0, south at
// lon 180), see nearly the same picture: no seam or pinwheel in the weather map.
TEST(RenderImage, PolesRenderCleanlyAndContinuously) {
  for (double lat : {90.0, -90.0})
    for (double alt : {10.0, 1500.0, 40000.0}) {
      const FrameImage img = render_preset("broken-cumulus", make_view(lat, 37.0, alt, 45.0, 10.0, "2026-06-21T12:00:00Z", 96, 54));
      EXPECT_EQ(count_bad_values(img), 0) << lat << " " << alt;
    }
  const FrameImage a = render_preset("broken-cumulus", make_view(89.99999, 0.0, 500.0, 0.0, 5.0, "2026-06-21T12:00:00Z"));
  const FrameImage b = render_preset("broken-cumulus", make_view(89.99999, 180.0, 500.0, 180.0, 5.0, "2026-06-21T12:00:00Z"));
  double diff = 0.0, sum = 0.0;
  for (size_t i = 0; i < a.rgba.size(); i += 4)
    for (int c = 0; c < 3; ++c) { diff += std::abs(a.rgba[i + c] - b.rgba[i + c]); sum += a.rgba[i + c]; }
  EXPECT_GT(a.stats.cloud_pixels, 100);
  EXPECT_LT(diff / sum, 0.05);
}

// View-dependent LUTs (sky view, aerial perspective) are recomputed only when their
// inputs change; reusing them gives exactly the image a recomputation would, up to the
// aerial-perspective volume's froxel placement. Turning the camera keeps the sky-view LUT
// (relative to the local vertical and the sun's azimuth) and, while the camera's frustum
// stays inside the volume's (kApMargin wider), the aerial-perspective froxels too; a
// volume built for another orientation changes the image only by its interpolation.
TEST(RenderImage, ViewLutsAreReusedOnlyWhileTheyServeTheView) {
  CloudRenderer& r = shared_renderer();
  r.set_weather(*weather::preset("broken-cumulus"));
  const ViewRequest v = make_view(47.45, 8.56, 500.0, 90.0, 10.0, kNoonZurich, 64, 36);
  const FrameImage first = r.render(v);
  const FrameImage again = r.render(v);
  EXPECT_FALSE(again.stats.view_luts_recomputed);
  EXPECT_EQ(first.rgba, again.rgba);
  ViewRequest turned = v;
  turned.attitude.heading_deg += 0.5;  // inside the volume's frustum (~2.5 deg wider on each side)
  const FrameImage turned_reused = r.render(turned);
  EXPECT_FALSE(turned_reused.stats.view_luts_recomputed);
  ViewRequest far_turned = v;
  far_turned.attitude.heading_deg += 4.0;  // beyond it
  const FrameImage far_img = r.render(far_turned);
  EXPECT_TRUE(far_img.stats.view_luts_recomputed);
  EXPECT_FALSE(far_img.stats.sky_view_recomputed);
  ViewRequest later = v;
  later.unix_time_s += 1800.0;  // the sun moves ~7 deg, its elevation by ~3 deg
  const FrameImage later_img = r.render(later);
  EXPECT_TRUE(later_img.stats.view_luts_recomputed);
  EXPECT_TRUE(later_img.stats.sky_view_recomputed);
  const FrameImage turned_recomputed = r.render(turned);  // both LUTs redone, the volume for `turned`
  EXPECT_TRUE(turned_recomputed.stats.sky_view_recomputed);
  double worst = 0.0;
  for (size_t k = 0; k < turned_reused.rgba.size(); ++k)
    worst = std::max(worst, std::abs(static_cast<double>(turned_reused.rgba[k]) - turned_recomputed.rgba[k]) /
                                (std::abs(turned_recomputed.rgba[k]) + 1e-4));
  std::printf("aerial-perspective volume of a view 0.5 deg away vs its own: worst relative difference %.2e\n", worst);
  EXPECT_LT(worst, 5e-3);
  const FrameImage back = r.render(v);  // inside the volume built for `turned`: reused
  EXPECT_FALSE(back.stats.view_luts_recomputed);
  double worst_back = 0.0;
  for (size_t k = 0; k < back.rgba.size(); ++k)
    worst_back = std::max(worst_back, std::abs(static_cast<double>(back.rgba[k]) - first.rgba[k]) /
                                          (std::abs(first.rgba[k]) + 1e-4));
  EXPECT_LT(worst_back, 5e-3);
  // (after the comparisons: these also move the ground shadow map's anchor and sun)
  ViewRequest near_noon = v;
  near_noon.unix_time_s += 60.0;  // 0.25 deg of azimuth, but the elevation stays within 1e-4 of its cosine:
  EXPECT_FALSE(r.render(near_noon).stats.sky_view_recomputed);  // the sky-view LUT is kept
  ViewRequest climbed = v;
  climbed.position.alt_m += 5.0;  // the sky-view LUT depends on altitude
  EXPECT_TRUE(r.render(climbed).stats.sky_view_recomputed);
}

// The sun disk is box-filtered over the pixel (composite.comp, sun_disk): at 64x36 (pixels of
// 0.94 deg, the disk 0.53 deg across) a camera panning across the sun in 0.01 deg steps sees
// no pixel jump (each step changes any pixel by < 5 % of the brightest one; a point-sampled
// disk jumps by 100 % when its edge crosses a pixel centre), and the disk's energy in the
// image, sum of L x pixel solid angle around it, stays the same wherever it falls (within 2 %).
TEST(RenderImage, SunDiskIsBoxFilteredOverThePixel) {
  CloudRenderer& r = shared_renderer();
  r.set_weather(*weather::preset("clear"));
  const double t = *geo::parse_utc_iso8601("2026-06-21T09:00:00Z");
  const geo::SolarPosition sp = geo::solar_position(t, 47.45, 8.56);
  const int W = 64, H = 36;
  const double p = 2.0 * std::tan(30.0 * 3.14159265358979 / 180.0) / W;  // pixel width at the centre, rad
  std::vector<float> prev;
  double worst_step = 0.0, brightest = 0.0, e_min = 1e30, e_max = 0.0;
  for (int k = 0; k <= 150; ++k) {
    ViewRequest v = make_view(47.45, 8.56, 500.0, sp.azimuth_deg - 0.75 + 0.01 * k, sp.elevation_deg + 0.3, "2026-06-21T09:00:00Z", W, H);
    const FrameImage img = r.render(v);
    size_t top = 0;
    for (size_t i = 1; i < img.rgba.size() / 4; ++i)
      if (img.rgba[4 * i + 1] > img.rgba[4 * top + 1]) top = i;
    brightest = std::max(brightest, static_cast<double>(img.rgba[4 * top + 1]));
    const int x0 = static_cast<int>(top % W), y0 = static_cast<int>(top / W);
    double e = 0.0;  // green radiance x pixel solid angle over the 5 x 5 pixels around the disk
    for (int y = std::max(0, y0 - 2); y <= std::min(H - 1, y0 + 2); ++y)
      for (int x = std::max(0, x0 - 2); x <= std::min(W - 1, x0 + 2); ++x) e += img.rgba[(static_cast<size_t>(y) * W + x) * 4 + 1] * p * p;
    e_min = std::min(e_min, e);
    e_max = std::max(e_max, e);
    if (!prev.empty())
      for (size_t i = 1; i < img.rgba.size(); i += 4) worst_step = std::max(worst_step, std::abs(static_cast<double>(img.rgba[i] - prev[i])));
    prev = img.rgba;
  }
  std::printf("sun disk: brightest pixel %.3g, worst change per 0.01 deg step %.3g (%.2f %%), disk energy %.4g..%.4g\n",
              brightest, worst_step, 100.0 * worst_step / brightest, e_min, e_max);
  EXPECT_LT(worst_step, 0.05 * brightest);
  EXPECT_LT(e_max / e_min, 1.02);
}

// The horizon is box-filtered over the pixel (composite.comp split_at_horizon: the fraction of the pixel's
// footprint below the horizon, from the ray elevations at its edges): (1) a clear view
// panned in pitch by 0.02 pixel per frame (rolled 20 deg, so the horizon crosses pixels
// diagonally) changes no pixel by more than 5 % of the ground/sky contrast in one step (a
// point-sampled horizon jumps by the whole contrast where it crosses a pixel centre);
// (2) on the horizon pixels the GPU value is closer to the CPU reference's 6 x 6-ray
// footprint than the reference's own centre ray is (the box filter is the footprint).
TEST(RenderImage, HorizonIsBoxFilteredOverThePixel) {
  CloudRenderer& r = shared_renderer();
  const weather::Weather w = *weather::preset("clear");
  r.set_weather(w);
  const int W = 32, H = 18;
  const double pixel_deg = 2.0 * std::atan(std::tan(30.0 * M_PI / 180.0) / W) * 180.0 / M_PI;
  const double dip_deg = std::acos(6371000.0 / 6373000.0) * 180.0 / M_PI;  // from 2 km
  ViewRequest v = make_view(47.45, 8.56, 2000.0, 200.0, -dip_deg, "2026-06-21T11:30:00Z", W, H);
  v.attitude.roll_deg = 20.0;
  std::vector<float> prev;
  double worst_step = 0.0, contrast = 0.0;
  for (int k = 0; k <= 60; ++k) {
    v.attitude.pitch_deg = -dip_deg - 0.6 * pixel_deg + 0.02 * pixel_deg * k;
    const FrameImage img = r.render(v);
    float lo = 1e30f, hi = 0.0f;
    for (size_t i = 1; i < img.rgba.size(); i += 4) { lo = std::min(lo, img.rgba[i]); hi = std::max(hi, img.rgba[i]); }
    contrast = std::max(contrast, static_cast<double>(hi - lo));
    if (!prev.empty())
      for (size_t i = 1; i < img.rgba.size(); i += 4) worst_step = std::max(worst_step, std::abs(static_cast<double>(img.rgba[i] - prev[i])));
    prev = img.rgba;
  }
  // (2) one view, the horizon through the middle rows
  v.attitude.pitch_deg = -dip_deg + 0.13 * pixel_deg;
  const FrameImage gpu = r.render(v);
  reference::ReferenceSettings centre, footprint;
  footprint.pixel_samples = 6;
  const FrameImage ref_c = reference::render_reference(v, w, centre);
  const FrameImage ref_f = reference::render_reference(v, w, footprint);
  double err_gpu = 0.0, err_centre = 0.0;
  int horizon_px = 0;
  for (size_t i = 0; i < gpu.rgba.size() / 4; ++i) {
    const double c = std::abs(ref_c.rgba[4 * i + 1] - ref_f.rgba[4 * i + 1]);
    if (c < 0.05 * contrast) continue;  // not a horizon pixel
    ++horizon_px;
    err_gpu += std::abs(gpu.rgba[4 * i + 1] - ref_f.rgba[4 * i + 1]);
    err_centre += c;
  }
  std::printf("horizon: contrast %.4g, worst change per 0.02 px pitch step %.3g (%.1f %% of it); on %d horizon pixels "
              "mean |GPU - 6x6 footprint| %.3g, |centre ray - footprint| %.3g\n",
              contrast, worst_step, 100.0 * worst_step / contrast, horizon_px, err_gpu / std::max(horizon_px, 1),
              err_centre / std::max(horizon_px, 1));
  EXPECT_LT(worst_step, 0.05 * contrast);
  ASSERT_GT(horizon_px, 10);
  EXPECT_LT(err_gpu, 0.5 * err_centre);
}

}  // namespace
}  // namespace cloudsvc::test
