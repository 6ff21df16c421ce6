// Shared helpers for the image tests: one headless GL context and renderer per test
// binary, views by name, and image statistics.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "geodesy/geodetic.h"
#include "geodesy/utc_time.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/image_output.h"
#include "weather/presets.h"

namespace cloudsvc::test {

// Lazily created, shared by all tests in the binary (context creation + shader JIT are
// the slow part on llvmpipe).
inline CloudRenderer& shared_renderer() {
  static std::unique_ptr<gl::EglContext> context = std::make_unique<gl::EglContext>();
  static std::unique_ptr<CloudRenderer> renderer = std::make_unique<CloudRenderer>();
  return *renderer;
}

inline ViewRequest make_view(double lat, double lon, double alt, double heading, double pitch,
                             const std::string& time_utc, int w = 160, int h = 90, double fov = 60.0) {
  ViewRequest v;
  v.position = {lat, lon, alt};
  v.attitude = {heading, pitch, 0.0};
  v.unix_time_s = *geo::parse_utc_iso8601(time_utc);
  v.width = w;
  v.height = h;
  v.fov_deg = fov;
  return v;
}

inline FrameImage render_preset(const std::string& preset, const ViewRequest& v, const RenderQuality& q = {}) {
  CloudRenderer& r = shared_renderer();
  r.set_weather(*weather::preset(preset));
  return r.render(v, q);
}

inline double mean_luminance(const FrameImage& img, int x0, int y0, int x1, int y1) {
  double s = 0.0;
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) { s += luminance(img.pixel(x, y)); ++n; }
  return n ? s / n : 0.0;
}

inline double mean_luminance(const FrameImage& img) { return mean_luminance(img, 0, 0, img.width, img.height); }

// Counts NaN, Inf and negative values over all channels.
inline int count_bad_values(const FrameImage& img) {
  int bad = 0;
  for (float v : img.rgba) bad += (!std::isfinite(v) || v < 0.0f) ? 1 : 0;
  return bad;
}

}  // namespace cloudsvc::test
