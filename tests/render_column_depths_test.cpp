// The diffuse light's column depths (RenderQuality::column_steps on the GPU,
// ReferenceSettings::column_depths on the CPU; docs/RENDERING.md "Light"): the GPU draws the
// reference's column model, and in a cumulus field that model differs from the homogeneous
// layer's. Against the path-traced truth: cloudbench --truth --column-steps N
// (docs/ACCURACY.md section 0).
#include <gtest/gtest.h>

#include <cstdio>

#include "render_test_support.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/image_metrics.h"
#include "renderer/reference/reference_renderer.h"
#include "weather/presets.h"

namespace cloudsvc::test {
namespace {

// Scattered cumulus from 3 km looking 25 degrees down under a sun 20 degrees high, and a
// cumulonimbus from below its anvil's height: the two kinds of scene where a column's cloud
// differs most from the layer's mean.
struct Case {
  const char* preset;
  const char* time;
  double alt_m, pitch_deg;
  bool thick;  // columns of ~10 km: the GPU's few quadratically spaced steps converge slowly
};

TEST(ColumnDepths, TheGpuDrawsTheReferencesColumns) {
  for (const Case& c : {Case{"scattered-cumulus", "2026-06-21T05:30Z", 3000.0, -25.0, false},
                        Case{"cumulonimbus", "2026-06-21T10:00Z", 1500.0, 5.0, true}}) {
    const weather::Weather w = *weather::preset(c.preset);
    const ViewRequest v = make_view(47.45, 8.56, c.alt_m, 90.0, c.pitch_deg, c.time, 32, 18, 60.0);
    reference::ReferenceSettings columns, homogeneous;
    columns.column_depths = true;
    const FrameImage ref_columns = reference::render_reference(v, w, columns);
    const FrameImage ref_homogeneous = reference::render_reference(v, w, homogeneous);
    CloudRenderer& r = shared_renderer();
    r.set_weather(w);
    RenderQuality with = *quality_preset("default"), without = with;
    with.column_steps = 6;
    const FrameImage gpu_columns = render_still_view(r, v, with);
    const FrameImage gpu_homogeneous = render_still_view(r, v, without);
    const double gpu_err = reference::compare_images(gpu_columns, ref_columns).relative_rmse;
    const double gpu_other = reference::compare_images(gpu_homogeneous, ref_columns).relative_rmse;
    const double models = reference::compare_images(ref_homogeneous, ref_columns).relative_rmse;
    const double gpu_homogeneous_err = reference::compare_images(gpu_homogeneous, ref_homogeneous).relative_rmse;
    EXPECT_EQ(gpu_columns.stats.nonfinite_pixels, 0);
    std::printf("%s: GPU columns vs reference columns %.3f (GPU homogeneous vs them %.3f); the two models in the "
                "reference differ by %.3f; GPU homogeneous vs reference homogeneous %.3f\n",
                c.preset, gpu_err, gpu_other, models, gpu_homogeneous_err);
    // Measured (2026-12-06): cumulus 0.185 against 0.857 and 0.851; cumulonimbus 0.167
    // against 0.514 and 0.515 (the renderers agree within 0.005 there on the homogeneous
    // model).
    // The two models differ by far more than the GPU's error in the one it draws ...
    EXPECT_GT(models, 2.5 * gpu_err);
    // ... and the GPU with columns draws the reference's column model, not the homogeneous one.
    EXPECT_LT(gpu_err, 0.4 * gpu_other);
    if (c.thick) {
      // Through a 10 km column the GPU's steps converge on the reference's: 0.167 at 6
      // steps, 0.117 at 24, 0.070 at 64.
      RenderQuality finer = with;
      finer.column_steps = 24;
      const double finer_err =
          reference::compare_images(render_still_view(r, v, finer), ref_columns).relative_rmse;
      std::printf("%s: 24 column steps %.3f\n", c.preset, finer_err);
      EXPECT_LT(finer_err, 0.85 * gpu_err);
    }
  }
}

}  // namespace
}  // namespace cloudsvc::test
