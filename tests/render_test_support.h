// Shared helpers for the image tests: one headless GL context and renderer per test
// binary, views by name, and image statistics.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

#include "geodesy/geodetic.h"
#include "geodesy/utc_time.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/image_output.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/reference_renderer.h"
#include "tests/make_view.h"
#include "weather/presets.h"

namespace cloudsvc::test {

// Lazily created, shared by all tests in the binary (context creation + shader JIT are
// the slow part on llvmpipe).
inline CloudRenderer& shared_renderer() {
  static std::unique_ptr<gl::EglContext> context = std::make_unique<gl::EglContext>();
  static std::unique_ptr<CloudRenderer> renderer = std::make_unique<CloudRenderer>();
  return *renderer;
}

// Writes img as PNG to $CLOUDSVC_TEST_IMAGES/<name>.png when that variable is set (for
// looking at what a test saw).
inline void maybe_save(std::string name, const FrameImage& img) {
  for (char& c : name) if (c == '/') c = '_';  // parameterised test names
  if (const char* dir = std::getenv("CLOUDSVC_TEST_IMAGES")) write_image(std::string(dir) + "/" + name + ".png", img);
}

// One frame of the default preset under weather w, marched in full through the pixel
// centres (no history, no footprint jitter), and the CPU reference of the same light model:
// the pair the tests of a field's shape compare. Saved as <name>_gpu and <name>_ref.
struct GpuAndReference {
  FrameImage gpu, ref;
};
inline GpuAndReference render_frame_and_reference(const weather::Weather& w, const ViewRequest& v,
                                                  const std::string& name) {
  CloudRenderer& r = shared_renderer();
  r.set_weather(w);
  RenderQuality q = *quality_preset("default");
  q.temporal_reuse = false;
  q.footprint_jitter = false;
  ViewRequest fresh = v;
  fresh.reset_history = true;
  GpuAndReference out{r.render(fresh, q), reference::render_reference(v, w, reference::same_light_model(q))};
  maybe_save(name + "_gpu", out.gpu);
  maybe_save(name + "_ref", out.ref);
  return out;
}

inline FrameImage render_weather(const weather::Weather& w, const ViewRequest& v, const RenderQuality& q = {}) {
  CloudRenderer& r = shared_renderer();
  r.set_weather(w);
  FrameImage img = r.render(v, q);
  EXPECT_EQ(img.stats.loop_capped_invocations, 0) << "the driver's loop cap cut rays short (FrameStats)";
  maybe_save(::testing::UnitTest::GetInstance()->current_test_info()->name() + std::string("_") + w.name, img);
  return img;
}

// The last of `frames` renders of the still view v at quality q, the first starting a new
// history: as cloudbench holds a view (17 frames = the first, which marches every pixel, and
// one 16-frame cycle of the 1/16-px presets).
inline FrameImage render_still_view(CloudRenderer& r, ViewRequest v, const RenderQuality& q, int frames = 17) {
  FrameImage img;
  for (int f = 0; f < frames; ++f) {
    v.frame_index = static_cast<std::uint32_t>(f);
    v.reset_history = f == 0;
    img = r.render(v, q);
    EXPECT_EQ(img.stats.loop_capped_invocations, 0) << "frame " << f << ": the driver's loop cap cut rays short";
  }
  return img;
}

inline FrameImage render_preset(const std::string& preset, const ViewRequest& v, const RenderQuality& q = {}) {
  return render_weather(*weather::preset(preset), v, q);
}

// One layer of the given type, for tests that need a known sky.
inline weather::Weather single_layer(weather::CloudType type, double base_m, double top_m, double coverage,
                                     std::uint32_t map_seed = 11) {
  weather::Weather w;
  w.name = "test-layer";
  w.map_seed = map_seed;
  weather::CloudLayer l;
  l.type = type;
  l.base_m = base_m;
  l.top_m = top_m;
  l.coverage = coverage;
  l.density_scale = weather::cloud_type_traits(type).default_density_scale;
  l.droplet_diameter_um = weather::cloud_type_traits(type).default_droplet_diameter_um;
  w.layers.push_back(l);
  return w;
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
