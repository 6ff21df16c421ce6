// The noise volumes' stochastic tiling (RendererConfig::noise_tiling, weather/noise_tiling.h)
// in the renderer: seen straight down from 60 km at Zurich (a 69 km view, 64 x 64 px, the
// default preset held still for 17 frames, as cloudbench --morphology), the cumulus field
// and the stratocumulus deck no longer repeat with the noise's period (the periodic
// autocorrelation peak of the opacity, renderer/reference/cloud_morphology.h, falls from
// the lattice's to that of a field without one), and the GPU draws the same clouds as the
// CPU reference with the same tiling (cloud pixels within 2 points, no non-finite pixel).
#include <gtest/gtest.h>

#include <cstdio>

#include "geodesy/utc_time.h"
#include "render_test_support.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/cloud_morphology.h"
#include "renderer/reference/reference_renderer.h"

namespace cloudsvc::test {
namespace {

TEST(NoiseTiling, CloudsStopRepeatingAndTheGpuDrawsTheReferenceField) {
  CloudRenderer& untiled = shared_renderer();  // creates the context
  RendererConfig config;
  config.noise_tiling = true;
  CloudRenderer tiled(config);
  reference::ReferenceSettings settings;
  settings.noise_tiling = true;
  const RenderQuality q = *quality_preset("default");
  for (const char* preset : {"scattered-cumulus", "stratocumulus-deck"}) {
    const weather::Weather w = *weather::preset(preset);
    const ViewRequest v = make_view(47.4, 8.5, 60000.0, 0.0, -90.0, "2026-06-21T10:00:00Z", 64, 64);
    untiled.set_weather(w);
    tiled.set_weather(w);
    const FrameImage before = render_still_view(untiled, v, q);
    const FrameImage gpu = render_still_view(tiled, v, q);
    const FrameImage ref = reference::render_reference(v, w, settings);
    maybe_save(std::string("noise_tiling_") + preset, gpu);
    const reference::Field o_before = reference::opacity_field(before), o_gpu = reference::opacity_field(gpu),
                           o_ref = reference::opacity_field(ref);
    const double peak_before = reference::periodic_autocorrelation_peak(o_before, 4.0, 32.0);
    const double peak_gpu = reference::periodic_autocorrelation_peak(o_gpu, 4.0, 32.0);
    const double peak_ref = reference::periodic_autocorrelation_peak(o_ref, 4.0, 32.0);
    const double c_gpu = reference::cloud_fraction(o_gpu), c_ref = reference::cloud_fraction(o_ref);
    std::printf("%s: periodic autocorrelation peak untiled %.3f, tiled GPU %.3f, tiled reference %.3f; cloud pixels "
                "GPU %.1f %%, reference %.1f %%, untiled %.1f %%\n",
                preset, peak_before, peak_gpu, peak_ref, 100.0 * c_gpu, 100.0 * c_ref,
                100.0 * reference::cloud_fraction(o_before));
    EXPECT_EQ(gpu.stats.nonfinite_pixels, 0) << preset;
    EXPECT_GT(peak_before, 0.3) << preset;  // the lattice of the periodic noise
    EXPECT_LT(peak_gpu, 0.12) << preset;
    EXPECT_LT(peak_ref, 0.12) << preset;
    EXPECT_GT(c_ref, 0.05) << preset;  // the view shows clouds
    EXPECT_NEAR(c_gpu, c_ref, 0.02) << preset;
  }
}

}  // namespace
}  // namespace cloudsvc::test
