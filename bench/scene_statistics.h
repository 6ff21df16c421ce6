// Per-scene error metrics beyond renderer/reference/image_metrics.h and their aggregation
// over a scene set (cloudbench's "Over scenes" section; issue 14). Header-only: every
// bench/*.cpp is an executable.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "renderer/api/frame_image.h"

namespace cloudsvc::bench {

// Opacity above which a reference pixel counts as cloud (FrameStats::cloud_pixels uses the same).
inline constexpr double kCloudOpacity = 0.01;

struct CloudRelativeError {
  double mean = std::numeric_limits<double>::quiet_NaN();  // NaN when no pixel is cloud
  std::int64_t pixels = 0;                                 // reference pixels with opacity > kCloudOpacity
};

// Mean over the reference's cloud pixels (opacity a > kCloudOpacity) and the rgb channels of
// |test - ref| / ref (linear radiance; channels with ref <= 0 are left out, which the
// reference's night-sky floor makes never happen). Same image size required.
inline CloudRelativeError cloud_relative_error(const FrameImage& test, const FrameImage& ref) {
  CloudRelativeError e;
  double sum = 0.0;
  std::int64_t n = 0;
  const size_t pixels = static_cast<size_t>(ref.width) * static_cast<size_t>(ref.height);
  for (size_t i = 0; i < pixels; ++i) {
    const float* r = &ref.rgba[i * 4];
    const float* t = &test.rgba[i * 4];
    if (!(r[3] > kCloudOpacity)) continue;
    ++e.pixels;
    for (int c = 0; c < 3; ++c) {
      if (!(r[c] > 0.0f)) continue;
      sum += std::abs(static_cast<double>(t[c]) - r[c]) / r[c];
      ++n;
    }
  }
  if (n > 0) e.mean = sum / static_cast<double>(n);
  return e;
}

// Mean over all pixels of the opacity difference test - ref: > 0 when the test image's
// clouds are larger (dilated silhouettes) or more opaque than the reference's, < 0 when
// smaller or thinner. Same image size required.
inline double opacity_bias(const FrameImage& test, const FrameImage& ref) {
  const size_t pixels = static_cast<size_t>(ref.width) * static_cast<size_t>(ref.height);
  double sum = 0.0;
  for (size_t i = 0; i < pixels; ++i) sum += static_cast<double>(test.rgba[i * 4 + 3]) - ref.rgba[i * 4 + 3];
  return pixels ? sum / static_cast<double>(pixels) : 0.0;
}

// The p-th percentile (p in [0, 100]) of the finite values of v, linearly interpolated between
// order statistics (rank p/100 (n - 1), numpy's default "linear" method); NaN if none.
inline double percentile(std::vector<double> v, double p) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const double rank = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(v.size() - 1);
  const size_t lo = static_cast<size_t>(std::floor(rank));
  const size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (rank - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

// Mean of the finite values of v; NaN if none.
inline double finite_mean(const std::vector<double>& v) {
  double s = 0.0;
  int n = 0;
  for (double x : v)
    if (std::isfinite(x)) { s += x; ++n; }
  return n ? s / n : std::numeric_limits<double>::quiet_NaN();
}

inline int finite_count(const std::vector<double>& v) {
  return static_cast<int>(std::count_if(v.begin(), v.end(), [](double x) { return std::isfinite(x); }));
}

// One configuration's error on one scene.
struct SceneError {
  double rmse = 0.0;             // linear radiance, W m^-2 sr^-1 nm^-1 (image_metrics.h)
  double rmse_over_naive = 0.0;  // rmse / the naive march's rmse on the same scene (NaN if that is 0)
  double psnr_db = 0.0;          // peak = the reference's largest rgb value
  double opacity_rmse = 0.0;     // RMSE of the opacity channel (silhouettes)
  double opacity_bias = 0.0;     // opacity_bias(): mean test - ref opacity (> 0: dilated or denser)
  double cloud_rel = 0.0;        // cloud_relative_error().mean (NaN: no cloud pixel)
};

// A configuration's errors over the scene set: means and the 90th percentile over scenes of
// each per-scene error (for PSNR, where higher is better, the 10th percentile: the value 90 %
// of the scenes reach or beat). Scenes where a metric is undefined (NaN) are left out of it.
struct OverScenes {
  int scenes = 0;
  double rel_mean = 0, rel_p90 = 0;          // rmse_over_naive
  double rmse_mean = 0, rmse_p90 = 0;
  double psnr_mean = 0, psnr_p10 = 0;
  double opacity_mean = 0, opacity_p90 = 0;
  double bias_mean = 0, bias_p90 = 0;        // opacity_bias
  double cloud_mean = 0, cloud_p90 = 0;
  int cloud_scenes = 0;                      // scenes with cloud pixels in the reference
};

inline OverScenes over_scenes(const std::vector<SceneError>& errors) {
  std::vector<double> rel, rmse, psnr, opacity, bias, cloud;
  for (const SceneError& e : errors) {
    rel.push_back(e.rmse_over_naive);
    rmse.push_back(e.rmse);
    psnr.push_back(e.psnr_db);
    opacity.push_back(e.opacity_rmse);
    bias.push_back(e.opacity_bias);
    cloud.push_back(e.cloud_rel);
  }
  OverScenes o;
  o.scenes = static_cast<int>(errors.size());
  o.rel_mean = finite_mean(rel);
  o.rel_p90 = percentile(rel, 90.0);
  o.rmse_mean = finite_mean(rmse);
  o.rmse_p90 = percentile(rmse, 90.0);
  o.psnr_mean = finite_mean(psnr);
  o.psnr_p10 = percentile(psnr, 10.0);
  o.opacity_mean = finite_mean(opacity);
  o.opacity_p90 = percentile(opacity, 90.0);
  o.bias_mean = finite_mean(bias);
  o.bias_p90 = percentile(bias, 90.0);
  o.cloud_mean = finite_mean(cloud);
  o.cloud_p90 = percentile(cloud, 90.0);
  o.cloud_scenes = finite_count(cloud);
  return o;
}

}  // namespace cloudsvc::bench
