// Cumulus layers drawn as individual domes (RendererConfig::cumulus_domes, weather/cumulus_domes.h)
// on the GPU and in the CPU reference (docs/MORPHOLOGY.md): both see the same clouds, and
// every pixel is finite.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "render_test_support.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/cloud_morphology.h"
#include "renderer/reference/reference_renderer.h"

namespace cloudsvc::test {
namespace {

CloudRenderer& dome_renderer() {
  static gl::EglContext context;
  static CloudRenderer r = [] {
    RendererConfig c;
    c.cumulus_domes = true;
    return CloudRenderer(c);
  }();
  return r;
}

TEST(CumulusDomesRendered, GpuAndReferenceSeeTheSameClouds) {
  for (const char* preset : {"scattered-cumulus", "broken-cumulus"}) {
    const weather::Weather w = *weather::preset(preset);
    ViewRequest v = make_view(47.4, 8.5, 20000.0, 0.0, -90.0, "2026-06-21T10:00:00Z", 64, 64);
    CloudRenderer& r = dome_renderer();
    r.set_weather(w);
    const FrameImage gpu = render_still_view(r, v, *quality_preset("default"));
    reference::ReferenceSettings rs;
    rs.cumulus_domes = true;
    const auto t0 = std::chrono::steady_clock::now();
    const FrameImage ref = reference::render_reference(v, w, rs);
    const double ref_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    maybe_save(std::string("domes_") + preset + "_gpu", gpu);
    maybe_save(std::string("domes_") + preset + "_reference", ref);
    EXPECT_EQ(gpu.stats.nonfinite_pixels, 0);
    const reference::Field og = reference::opacity_field(gpu), orf = reference::opacity_field(ref);
    const double cg = reference::cloud_fraction(og), cr = reference::cloud_fraction(orf);
    const double ag = reference::periodic_autocorrelation_peak(og, 4.0, 32.0);
    const double ar = reference::periodic_autocorrelation_peak(orf, 4.0, 32.0);
    std::printf("%s: cloud pixels reference %.1f %%, GPU %.1f %%; autocorrelation peak %.3f / %.3f (reference %.1f s)\n",
                preset, 100.0 * cr, 100.0 * cg, ar, ag, ref_s);
    EXPECT_GT(cr, 0.05) << preset;
    EXPECT_NEAR(cg, cr, 0.03) << preset;
    EXPECT_NEAR(ag, ar, 0.05) << preset;
  }
}

// Only frames with a dome layer in reach carry the dome path (renderer/density_programs.h;
// on llvmpipe it would cost every density evaluation): a stratus deck, or cumulus the
// weather map clears around the camera, runs the programs without it, and draws the same
// image as a renderer without domes.
TEST(CumulusDomesRendered, FramesWithoutDomeLayersInReachRunNoDomeCode) {
  ViewRequest v = make_view(47.4, 8.5, 3000.0, 30.0, 5.0, "2026-06-21T10:00:00Z", 48, 27);
  CloudRenderer& r = dome_renderer();
  r.set_weather(*weather::preset("scattered-cumulus"));
  EXPECT_EQ(render_still_view(r, v, *quality_preset("default")).stats.dome_layers, 1);
  const weather::Weather stratus = *weather::preset("overcast-stratus");
  r.set_weather(stratus);
  const FrameImage with = render_still_view(r, v, *quality_preset("default"));
  EXPECT_EQ(with.stats.dome_layers, 0);
  weather::Weather cleared = *weather::preset("scattered-cumulus");
  cleared.layers[0].coverage = 0.0;
  r.set_weather(cleared);
  EXPECT_EQ(render_still_view(r, v, *quality_preset("default")).stats.dome_layers, 0);
  CloudRenderer plain;
  plain.set_weather(stratus);
  const FrameImage without = render_still_view(plain, v, *quality_preset("default"));
  ASSERT_EQ(with.rgba.size(), without.rgba.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < with.rgba.size(); ++i) worst = std::max(worst, std::abs(double(with.rgba[i]) - without.rgba[i]));
  EXPECT_EQ(worst, 0.0) << "a stratus frame differs with domes enabled";
}

}  // namespace
}  // namespace cloudsvc::test
