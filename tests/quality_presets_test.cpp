// Quality presets: `default` is the march the accuracy floors are asserted for
// (accuracy_reference_vs_gpu_test renders with RenderQuality{}), `naive` is the uniform
// baseline, and the front presets grow in cost.
#include <gtest/gtest.h>

#include "renderer/density_programs.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/reference_renderer.h"

namespace cloudsvc {
namespace {

bool same_march(const RenderQuality& a, const RenderQuality& b) {
  return a.primary_steps == b.primary_steps && a.light_steps == b.light_steps &&
         a.ground_shadow_steps == b.ground_shadow_steps &&
         a.step_growth_ref_m == b.step_growth_ref_m && a.long_step_factor == b.long_step_factor &&
         a.level_of_detail == b.level_of_detail && a.cloud_resolution_divisor == b.cloud_resolution_divisor &&
         a.ground_shadow_map == b.ground_shadow_map;
}

// The default preset marches RenderQuality{}'s march (the one the accuracy floors are
// asserted for, at the pixel footprint), 1/16 of the pixels per frame, each frame through
// another point of the pixel; every temporal preset samples the footprint, the naive
// baseline and RenderQuality{} the pixel centre.
TEST(QualityPresets, DefaultIsTheMarchTheAccuracyFloorsCoverWithTemporalReuse) {
  const auto d = quality_preset("default");
  ASSERT_TRUE(d);
  EXPECT_TRUE(same_march(*d, RenderQuality{}));
  EXPECT_TRUE(d->temporal_reuse);
  EXPECT_EQ(d->temporal_stride, 4);
  EXPECT_TRUE(d->footprint_jitter);
  EXPECT_FALSE(RenderQuality{}.temporal_reuse);
  EXPECT_FALSE(RenderQuality{}.footprint_jitter);
  for (const std::string& name : quality_preset_names())
    EXPECT_EQ(quality_preset(name)->footprint_jitter, quality_preset(name)->temporal_reuse) << name;
}

TEST(QualityPresets, NaiveIsTheUniformBaseline) {
  const auto n = quality_preset("naive");
  ASSERT_TRUE(n);
  EXPECT_EQ(n->primary_steps, 64);
  EXPECT_EQ(n->light_steps, 6);
  EXPECT_EQ(n->step_growth_ref_m, 0.0);
  // no skips: every step in full, every pixel every frame, shadows marched per pixel
  EXPECT_EQ(n->long_step_factor, 1);
  EXPECT_FALSE(n->level_of_detail);
  EXPECT_EQ(n->cloud_resolution_divisor, 1);
  EXPECT_FALSE(n->temporal_reuse);
  EXPECT_FALSE(n->ground_shadow_map);
}

TEST(QualityPresets, FrontPresetsGrowInCostAndUnknownNamesAreRejected) {
  int prev = 0;
  for (const char* name : {"low", "medium", "high", "ultra"}) {
    const auto q = quality_preset(name);
    ASSERT_TRUE(q) << name;
    // march work per pixel and frame, amortised over the reuse
    const int stride = q->temporal_reuse ? q->temporal_stride : 1;
    const int cost = q->primary_steps * (1 + q->light_steps) /
                     (stride * stride * q->cloud_resolution_divisor * q->cloud_resolution_divisor);
    EXPECT_GT(cost, prev) << name;
    prev = cost;
  }
  EXPECT_FALSE(quality_preset("Ultra"));
  EXPECT_FALSE(quality_preset(""));
  EXPECT_EQ(quality_preset_names().back(), "default");
}

// Every preset's marches but ultra's leave llvmpipe's loop budget for the dome sub-grid's loop (the
// faster variant); a march of tens of thousands of light samples per ray, like the accuracy
// tests' fine march, gets the written-out variant instead of running into the cap.
TEST(QualityPresets, EveryPresetButUltraFitsTheDensityLoopsAndTheFineMarchDoesNot) {
  for (const std::string& name : quality_preset_names()) {
    const auto q = quality_preset(name);
    if (!q) continue;  // CPU-only names
    EXPECT_EQ(density_loops_fit(*q), name != "ultra") << name;
  }
  // ultra's own columns, marched from each lit sample, are what take it over the budget
  RenderQuality ultra_volume = *quality_preset("ultra");
  ultra_volume.column_volume = true;
  EXPECT_TRUE(density_loops_fit(ultra_volume));
  RenderQuality fine;
  fine.primary_steps = 1024;
  fine.light_steps = 32;
  EXPECT_FALSE(density_loops_fit(fine));
}

// high and ultra light each sample with the depths of its own column, marched in 8 steps
// (the column volume's texels blur cumulus columns: docs/ACCURACY.md section 0); the
// cheaper presets keep the homogeneous layer's depths, and each is compared with the
// reference of its own light model.
TEST(QualityPresets, HighAndUltraMarchEachSamplesOwnColumn) {
  for (const std::string& name : quality_preset_names()) {
    const auto q = quality_preset(name);
    if (!q) continue;
    const bool columns = name == "high" || name == "ultra";
    EXPECT_EQ(q->column_steps, columns ? 8 : 0) << name;
    if (columns) {
      EXPECT_FALSE(q->column_volume) << name;
    }
    EXPECT_FALSE(q->sun_slab_tilt) << name;
    EXPECT_EQ(reference::same_light_model(*q).column_depths, columns) << name;
  }
}

}  // namespace
}  // namespace cloudsvc
