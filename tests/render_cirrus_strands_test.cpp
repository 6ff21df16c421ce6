// Cirrus strands on the GPU (weather/noise_shaping.h): a cirrus layer seen straight up from
// 500 m at Zurich, the camera heading east (so the strands run along the image's columns),
// 96 x 96 px over 60 degrees (~10 km of the layer), one frame marched in full through the
// pixel centres. The opacity stays correlated several times as far east-west as
// north-south, and the GPU draws the CPU reference's field (the same shaping: the opacity
// images correlate and their means agree).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "render_test_support.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/cloud_morphology.h"
#include "renderer/reference/reference_renderer.h"

namespace cloudsvc::test {
namespace {

// The first lag (px) at which the opacity's autocorrelation along x (dx = 1) or y falls
// below 1/2, linear between lags.
double half_length_px(const reference::Field& f, int dx, int dy) {
  double mean = 0.0, var = 0.0;
  for (double v : f.v) mean += v;
  mean /= static_cast<double>(f.v.size());
  for (double v : f.v) var += (v - mean) * (v - mean);
  var /= static_cast<double>(f.v.size());
  double prev = 1.0;
  for (int lag = 1; lag < f.width / 2; ++lag) {
    double c = 0.0;
    int n = 0;
    for (int y = 0; y + lag * dy < f.height; ++y)
      for (int x = 0; x + lag * dx < f.width; ++x, ++n) c += (f.at(x, y) - mean) * (f.at(x + lag * dx, y + lag * dy) - mean);
    const double r = c / n / var;
    if (r < 0.5) return lag - (0.5 - r) / (prev - r);
    prev = r;
  }
  return f.width / 2.0;
}

double correlation(const reference::Field& a, const reference::Field& b) {
  double ma = 0.0, mb = 0.0;
  for (size_t i = 0; i < a.v.size(); ++i) ma += a.v[i], mb += b.v[i];
  ma /= a.v.size();
  mb /= b.v.size();
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (size_t i = 0; i < a.v.size(); ++i) {
    ab += (a.v[i] - ma) * (b.v[i] - mb);
    aa += (a.v[i] - ma) * (a.v[i] - ma);
    bb += (b.v[i] - mb) * (b.v[i] - mb);
  }
  return ab / std::sqrt(aa * bb);
}

TEST(CirrusStrands, TheGpuDrawsEastWestStrandsAsTheReferenceDoes) {
  weather::Weather w = single_layer(weather::CloudType::Cirrus, 9000.0, 10000.0, 0.6, 7);
  w.layers[0].wind = {30.0, 8.0};
  const ViewRequest v = make_view(47.45, 8.0, 500.0, 90.0, 90.0, "2026-06-21T10:00:00Z", 96, 96, 60.0);
  const auto [gpu, ref] = render_frame_and_reference(w, v, "cirrus_strands");
  EXPECT_EQ(gpu.stats.nonfinite_pixels, 0);
  const reference::Field og = reference::opacity_field(gpu), orf = reference::opacity_field(ref);
  // looking straight up heading east, the image's columns run east-west
  const double along_gpu = half_length_px(og, 0, 1), across_gpu = half_length_px(og, 1, 0);
  const double along_ref = half_length_px(orf, 0, 1), across_ref = half_length_px(orf, 1, 0);
  double mean_gpu = 0.0, mean_ref = 0.0;
  for (size_t i = 0; i < og.v.size(); ++i) mean_gpu += og.v[i], mean_ref += orf.v[i];
  mean_gpu /= og.v.size();
  mean_ref /= orf.v.size();
  const double corr = correlation(og, orf);
  std::printf("opacity correlation half-length east-west / north-south: GPU %.1f / %.1f px (ratio %.2f), reference "
              "%.1f / %.1f px (ratio %.2f); mean opacity GPU %.4f reference %.4f; GPU-reference correlation %.3f\n",
              along_gpu, across_gpu, along_gpu / across_gpu, along_ref, across_ref, along_ref / across_ref, mean_gpu,
              mean_ref, corr);
  EXPECT_GT(mean_ref, 0.02) << "the view shows cirrus";
  EXPECT_GT(along_gpu / across_gpu, 2.5);
  EXPECT_GT(along_ref / across_ref, 2.5);
  EXPECT_GT(corr, 0.9);
  EXPECT_NEAR(mean_gpu / mean_ref, 1.0, 0.1);
}

}  // namespace
}  // namespace cloudsvc::test
