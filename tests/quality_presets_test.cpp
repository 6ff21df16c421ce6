// Quality presets: `default` is the march the accuracy floors are asserted for
// (accuracy_reference_vs_gpu_test renders with RenderQuality{}), `naive` is the uniform
// baseline, and the front presets grow in cost.
#include <gtest/gtest.h>

#include "renderer/quality_presets.h"

namespace cloudsvc {
namespace {

bool same(const RenderQuality& a, const RenderQuality& b) {
  return a.primary_steps == b.primary_steps && a.light_steps == b.light_steps && a.ms_octaves == b.ms_octaves &&
         a.ground_shadow_steps == b.ground_shadow_steps && a.ms_a == b.ms_a && a.ms_b == b.ms_b && a.ms_c == b.ms_c &&
         a.step_growth_ref_m == b.step_growth_ref_m;
}

TEST(QualityPresets, DefaultIsTheMarchTheAccuracyFloorsCover) {
  ASSERT_TRUE(quality_preset("default"));
  EXPECT_TRUE(same(*quality_preset("default"), RenderQuality{}));
}

TEST(QualityPresets, NaiveIsTheUniformBaseline) {
  const auto n = quality_preset("naive");
  ASSERT_TRUE(n);
  EXPECT_EQ(n->primary_steps, 64);
  EXPECT_EQ(n->light_steps, 6);
  EXPECT_EQ(n->step_growth_ref_m, 0.0);
}

TEST(QualityPresets, FrontPresetsGrowInCostAndUnknownNamesAreRejected) {
  int prev = 0;
  for (const char* name : {"low", "medium", "high", "ultra"}) {
    const auto q = quality_preset(name);
    ASSERT_TRUE(q) << name;
    const int cost = q->primary_steps * (1 + q->light_steps);
    EXPECT_GT(cost, prev) << name;
    prev = cost;
  }
  EXPECT_FALSE(quality_preset("Ultra"));
  EXPECT_FALSE(quality_preset(""));
  EXPECT_EQ(quality_preset_names().back(), "default");
}

}  // namespace
}  // namespace cloudsvc
