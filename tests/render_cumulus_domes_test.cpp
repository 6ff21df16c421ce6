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

}  // namespace
}  // namespace cloudsvc::test
