// The weather's visibility (weather::Weather::visibility_m) drawn as haze: the atmosphere's
// aerosol is scaled so that the sea-level meteorological optical range is the visibility
// (model::atmosphere::aerosol_scale_for_visibility). Checked on images, the way an observer
// measures visibility (Koschmieder's law): a black object seen against the horizon sky at a
// distance d has the contrast C = e^{-beta d}, which is 5 % at d = V. Here the black object
// is the ground (albedo 0) seen from 10 m, row by row at distances of 0.2-1.5 V; the GPU
// and the CPU reference both give back the visibility they were given, and agree.
// Koschmieder's law holds for air whose light is the same all along the path; in haze the
// sun's light falls by ~0.1 % per metre towards the ground (the aerosol above a point
// thins with height), so the 10 m the path descends make the contrast read ~4-9 % long on
// the reference (3262 m for 3000, 10365 m for 10000): hence 12 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "render_test_support.h"
#include "renderer/model/atmosphere_constants.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/reference_renderer.h"

namespace cloudsvc::test {
namespace {

constexpr int kW = 8, kH = 128;
constexpr double kCameraAlt = 10.0, kPitchDeg = -0.25, kVerticalFovDeg = 0.8;
constexpr double kEarthR = 6.371e6;  // the distances below are insensitive to the exact radius

double row_green(const FrameImage& img, int y) {
  double s = 0.0;
  for (int x = 0; x < img.width; ++x) s += img.rgba[4 * (static_cast<std::size_t>(y) * img.width + x) + 1];
  return s / img.width;
}

// Elevation of row y's centre (rad) and, for rows below the horizon, the distance to the
// ground along it (m); 0 above the horizon.
double row_elevation(int y) {
  const double t = (1.0 - 2.0 * (y + 0.5) / kH) * std::tan(0.5 * kVerticalFovDeg * M_PI / 180.0);
  return kPitchDeg * M_PI / 180.0 + std::atan(t);
}
double ground_distance(double elevation) {
  const double rc = kEarthR + kCameraAlt, s = std::sin(-elevation);
  const double disc = rc * rc * s * s - (2.0 * kEarthR * kCameraAlt + kCameraAlt * kCameraAlt);
  return elevation < 0.0 && disc > 0.0 ? rc * s - std::sqrt(disc) : 0.0;
}

ViewRequest haze_view() {
  // horizontal field of view for the 2.4 deg vertical one at this aspect
  const double fov_h = 2.0 * std::atan(std::tan(0.5 * kVerticalFovDeg * M_PI / 180.0) * kW / kH) * 180.0 / M_PI;
  return make_view(47.45, 8.56, kCameraAlt, 0.0, kPitchDeg, "2026-06-21T10:00Z", kW, kH, fov_h);  // north, sun behind
}

// The visibility an observer reads off the image: beta from C(d) = e^{-beta d} over the
// ground rows at 0.2-1.5 V (least squares through the origin in -ln C vs d), the horizon
// sky from the top row (+0.15 deg); V = -ln 0.05 / beta.
double measured_visibility(const FrameImage& img, double V) {
  const double sky = row_green(img, 0);  // the top row: +0.15 deg
  double sdd = 0.0, sdl = 0.0;
  for (int y = 0; y < kH; ++y) {
    const double d = ground_distance(row_elevation(y));
    if (d < 0.2 * V || d > 1.5 * V) continue;
    const double contrast = 1.0 - row_green(img, y) / sky;
    if (!(contrast > 0.0)) continue;
    sdd += d * d;
    sdl += d * -std::log(contrast);
  }
  return sdd > 0.0 ? -std::log(model::atmosphere::kVisibilityContrast) / (sdl / sdd) : 0.0;
}

TEST(Visibility, TheImageShowsTheVisibilityGiven) {
  for (double V : {3000.0, 10000.0}) {
    weather::Weather w;
    w.ground_albedo = 0.0;  // a black object
    w.visibility_m = V;
    const ViewRequest v = haze_view();
    reference::ReferenceSettings rs;
    rs.atmosphere_step_m = 50.0;  // steps well below the hazy paths' few km
    const FrameImage ref = reference::render_reference(v, w, rs);
    const FrameImage gpu = render_weather(w, v, *quality_preset("default"));
    const double v_ref = measured_visibility(ref, V), v_gpu = measured_visibility(gpu, V);
    std::printf("visibility %.0f m: measured on the reference %.0f m, on the GPU %.0f m\n", V, v_ref, v_gpu);
    EXPECT_NEAR(v_ref, V, 0.12 * V);
    EXPECT_NEAR(v_gpu, V, 0.12 * V);
    double worst = 0.0;  // the rows GPU vs reference
    for (int y = 0; y < kH; ++y) worst = std::max(worst, std::abs(row_green(gpu, y) / row_green(ref, y) - 1.0));
    std::printf("  largest row difference GPU vs reference %.3f\n", worst);
    EXPECT_LT(worst, 0.07);  // measured 0.049 (3 km: the horizon sky 5 % dark), 0.021
    EXPECT_EQ(count_bad_values(gpu), 0);
  }
}

}  // namespace
}  // namespace cloudsvc::test
