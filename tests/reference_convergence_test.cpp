// Convergence of the reference renderer (renderer/reference/reference_renderer.h): halving
// the cloud and light-march steps, and separately the atmosphere step, changes tiny images
// of four kinds of scene by less than a stated tolerance (relative RMSE of linear radiance,
// image_metrics.h). The numbers are printed; docs/REFERENCE.md quotes them. The clear sky
// has no clouds to refine; the atmosphere tables (Psi_ms, E_sky) have their own convergence
// test in reference_atmosphere_test.cpp and are not rebuilt here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "geodesy/utc_time.h"
#include "renderer/reference/image_metrics.h"
#include "renderer/reference/reference_renderer.h"
#include "tests/sanitizer_build.h"
#include "weather/presets.h"

namespace cloudsvc::reference {
namespace {

constexpr int kWidth = 48, kHeight = 27;
constexpr double kTolerance = 0.01;  // relative RMSE between a render and its half-step twin

struct Scene {
  const char* name;
  const char* preset;
  double alt_m, heading_deg, pitch_deg;
  const char* time_utc;
};

// Zurich area, midsummer 2026 (solar noon ~11:26 UTC, sunset ~19:26 UTC). Headings keep
// the sun disk out of the frame (a one-pixel disk would dominate any RMSE).
const Scene kBrokenCumulusFromBelow{"broken cumulus from below", "broken-cumulus", 500.0, 200.0, 30.0,
                                    "2026-06-21T11:30:00Z"};
const Scene kInsideStratus{"inside stratus", "overcast-stratus", 650.0, 90.0, 0.0, "2026-06-21T11:30:00Z"};
const Scene kAboveDeckAtSunset{"above stratocumulus deck, sunset", "stratocumulus-deck", 3000.0, 270.0, -12.0,
                               "2026-06-21T19:05:00Z"};
const Scene kClearSky{"clear sky", "clear", 500.0, 200.0, 10.0, "2026-06-21T11:30:00Z"};

FrameImage render(const Scene& s, const ReferenceSettings& settings) {
  ViewRequest v;
  v.position = {47.45, 8.56, s.alt_m};
  v.attitude = {s.heading_deg, s.pitch_deg, 0.0};
  v.unix_time_s = *geo::parse_utc_iso8601(s.time_utc);
  v.width = kWidth;
  v.height = kHeight;
  v.fov_deg = 60.0;
  FrameImage img = render_reference(v, *weather::preset(s.preset), settings);
  EXPECT_EQ(img.stats.nonfinite_pixels, 0) << s.name;
  return img;
}

// Renders at the default settings and with the chosen steps halved; returns the relative RMSE.
double halving_error(const Scene& s, bool clouds, bool atmosphere) {
  const ReferenceSettings base;
  ReferenceSettings half = base;
  if (clouds) {
    half.cloud_step_m *= 0.5;
    half.light_step_m *= 0.5;
  }
  if (atmosphere) half.atmosphere_step_m *= 0.5;
  const FrameImage a = render(s, base);
  const FrameImage b = render(s, half);
  const ImageDifference d = compare_images(a, b);
  std::printf("%-36s halving %-10s: rel. RMSE %.2e  max |diff| %.2e at (%d, %d) (mean %.3e)  opacity RMSE %.1e  "
              "%.1f / %.1f s, %.0f / %.0f density evals per pixel\n",
              s.name, clouds ? "cloud+light" : "atmosphere", d.relative_rmse, d.max_error, d.max_error_x,
              d.max_error_y, d.mean_reference, d.opacity_rmse, a.stats.render_ms / 1000.0, b.stats.render_ms / 1000.0,
              a.stats.density_evals_per_pixel, b.stats.density_evals_per_pixel);
  return d.relative_rmse;
}

// One test for all scenes: the atmosphere tables and inputs are built once per process.
TEST(ReferenceConvergence, HalvingTheStepsChangesTheImageByLessThanOnePercent) {
  if (test::kSanitizerBuild) GTEST_SKIP() << test::kSlowUnderSanitizers
                                            << "; the ReferenceClouds tests render these paths here";
  EXPECT_LT(halving_error(kBrokenCumulusFromBelow, true, false), kTolerance) << kBrokenCumulusFromBelow.name;
  EXPECT_LT(halving_error(kInsideStratus, true, false), kTolerance) << kInsideStratus.name;
  EXPECT_LT(halving_error(kAboveDeckAtSunset, true, false), kTolerance) << kAboveDeckAtSunset.name;
  EXPECT_LT(halving_error(kAboveDeckAtSunset, false, true), kTolerance) << kAboveDeckAtSunset.name;
  EXPECT_LT(halving_error(kClearSky, false, true), kTolerance) << kClearSky.name;
}

}  // namespace
}  // namespace cloudsvc::reference

namespace cloudsvc::reference {
namespace {

// Footprint sampling (ReferenceSettings::pixel_samples = n): the mean of the n x n
// sub-pixel centre rays. At W x H with n = 2 those rays are exactly the pixel-centre rays of
// the same view at 2W x 2H, so the supersampled image must equal the 2 x 2 box average of
// the doubled image; and it must differ from the centre samples where the image has edges.
TEST(ReferenceFootprint, TwoByTwoSamplesAreTheBoxAverageOfTheDoubledImage) {
  const Scene& s = kBrokenCumulusFromBelow;
  ViewRequest v;
  v.position = {47.45, 8.56, s.alt_m};
  v.attitude = {s.heading_deg, s.pitch_deg, 0.0};
  v.unix_time_s = *geo::parse_utc_iso8601(s.time_utc);
  v.fov_deg = 60.0;
  v.width = 24;
  v.height = 14;
  ReferenceSettings centre, footprint;
  footprint.pixel_samples = 2;
  const FrameImage a = render_reference(v, *weather::preset(s.preset), footprint);
  const FrameImage c = render_reference(v, *weather::preset(s.preset), centre);
  ViewRequest v2 = v;
  v2.width = 2 * v.width;
  v2.height = 2 * v.height;
  const FrameImage b = render_reference(v2, *weather::preset(s.preset), centre);
  double worst = 0.0, moved = 0.0;
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x)
      for (int ch = 0; ch < 4; ++ch) {
        double box = 0.0;
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 2; ++i)
            box += b.rgba[(static_cast<size_t>(2 * y + j) * v2.width + (2 * x + i)) * 4 + ch];
        box *= 0.25;
        const size_t k = (static_cast<size_t>(y) * v.width + x) * 4 + ch;
        worst = std::max(worst, std::abs(a.rgba[k] - box) / (std::abs(box) + 1e-6));
        moved = std::max(moved, std::abs(a.rgba[k] - c.rgba[k]) / (std::abs(c.rgba[k]) + 1e-3));
      }
  std::printf("2x2 footprint vs box of the doubled image: worst relative difference %.2e; vs the centre: %.2e\n", worst,
              moved);
  EXPECT_LT(worst, 1e-5);   // float output rounding
  EXPECT_GT(moved, 1e-2);   // the footprint is not the centre at cloud edges
  // the stats count every sub-pixel ray's evaluations (3.76x the centre's here: other rays)
  EXPECT_GT(a.stats.density_evals_per_pixel, 3.0 * c.stats.density_evals_per_pixel);
  EXPECT_LT(a.stats.density_evals_per_pixel, 5.0 * c.stats.density_evals_per_pixel);
}

}  // namespace
}  // namespace cloudsvc::reference
