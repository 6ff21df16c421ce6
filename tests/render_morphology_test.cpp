// The clouds' morphology is a property of the density field, not of the renderer: the CPU
// reference (its own march and light, docs/REFERENCE.md) and the GPU's default preset see
// the same clouds straight down from 20 km (cloudbench --morphology --reference-size:
// renderer/reference/cloud_morphology.h). Checked on a cumulus field and a stratocumulus
// deck at Zurich, 64 x 64 px: the fraction of cloud pixels (opacity > 0.5) within 2 points
// and the periodic autocorrelation peak within 0.05.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "geodesy/utc_time.h"
#include "render_test_support.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/cloud_morphology.h"
#include "renderer/reference/reference_renderer.h"

namespace cloudsvc::test {
namespace {

TEST(Morphology, CpuReferenceAndGpuSeeTheSameClouds) {
  for (const char* preset : {"scattered-cumulus", "stratocumulus-deck"}) {
    const weather::Weather w = *weather::preset(preset);
    ViewRequest v = make_view(47.4, 8.5, 20000.0, 0.0, -90.0, "2026-06-21T10:00:00Z", 64, 64);
    CloudRenderer& r = shared_renderer();
    r.set_weather(w);
    const FrameImage gpu = render_still_view(r, v, *quality_preset("default"));  // still, as cloudbench
    const FrameImage ref = reference::render_reference(v, w, reference::ReferenceSettings{});
    const reference::Field og = reference::opacity_field(gpu), orf = reference::opacity_field(ref);
    const double cg = reference::cloud_fraction(og), cr = reference::cloud_fraction(orf);
    const double ag = reference::periodic_autocorrelation_peak(og, 4.0, 32.0);
    const double ar = reference::periodic_autocorrelation_peak(orf, 4.0, 32.0);
    std::printf("%s: cloud pixels reference %.1f %%, GPU %.1f %%; periodic autocorrelation peak %.3f / %.3f\n", preset,
                100.0 * cr, 100.0 * cg, ar, ag);
    EXPECT_GT(cr, 0.05) << preset;  // the view shows clouds
    EXPECT_NEAR(cg, cr, 0.02) << preset;
    EXPECT_NEAR(ag, ar, 0.05) << preset;
  }
}

}  // namespace
}  // namespace cloudsvc::test
