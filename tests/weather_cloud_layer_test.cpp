// Cloud types, their traits and Weather validation (weather/cloud_layer.h).
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <limits>
#include <string>

#include "weather/cloud_layer.h"

namespace cloudsvc::weather {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Weather one_layer(CloudLayer l) {
  Weather w;
  w.name = "test";
  w.layers = {l};
  return w;
}

CloudLayer cumulus() {
  CloudLayer l = default_layer(CloudType::Cumulus);
  l.base_m = 1000;
  l.top_m = 2000;
  return l;
}

TEST(CloudTypeNames, RoundTripForEveryType) {
  EXPECT_EQ(all_cloud_types().size(), 10u);
  for (CloudType t : all_cloud_types()) {
    const std::string_view name = cloud_type_name(t);
    ASSERT_FALSE(name.empty());
    for (char c : name) EXPECT_FALSE(std::isupper(static_cast<unsigned char>(c))) << name;
    EXPECT_EQ(cloud_type_from_name(name), t) << name;
  }
  EXPECT_EQ(cloud_type_name(CloudType::Cumulonimbus), "cumulonimbus");
  EXPECT_EQ(static_cast<int>(CloudType::Stratus), 10);  // CIGI numbering
}

TEST(CloudTypeNames, AliasesAndCase) {
  EXPECT_EQ(cloud_type_from_name("cb"), CloudType::Cumulonimbus);
  EXPECT_EQ(cloud_type_from_name("CU"), CloudType::Cumulus);
  EXPECT_EQ(cloud_type_from_name("sc"), CloudType::Stratocumulus);
  EXPECT_EQ(cloud_type_from_name("st"), CloudType::Stratus);
  EXPECT_EQ(cloud_type_from_name("Ci"), CloudType::Cirrus);
  EXPECT_EQ(cloud_type_from_name("Cumulus"), CloudType::Cumulus);
  EXPECT_FALSE(cloud_type_from_name("cumulus-congestus").has_value());
  EXPECT_FALSE(cloud_type_from_name("").has_value());
}

TEST(CloudTypeTraits, DefaultsOfEveryTypeValidate) {
  for (CloudType t : all_cloud_types()) {
    const CloudLayer l = default_layer(t);
    EXPECT_EQ(validate(one_layer(l)), "") << cloud_type_name(t);
    const HeightProfile& p = cloud_type_traits(t).profile;
    EXPECT_GT(p.bottom_ramp, 0.0f);
    EXPECT_LE(p.bottom_ramp + p.top_ramp, 1.0f) << cloud_type_name(t);
  }
}

TEST(CloudTypeTraits, PhysicallyOrdered) {
  const auto& st = cloud_type_traits(CloudType::Stratus);
  const auto& cu = cloud_type_traits(CloudType::Cumulus);
  const auto& cb = cloud_type_traits(CloudType::Cumulonimbus);
  const auto& ci = cloud_type_traits(CloudType::Cirrus);
  // Stratus: low, thin, flat, small droplets.
  EXPECT_LT(st.default_top_m - st.default_base_m, cu.default_top_m - cu.default_base_m);
  EXPECT_LT(st.default_droplet_diameter_um, cu.default_droplet_diameter_um);
  EXPECT_TRUE(st.stratiform);
  // Cumulus: flat base, rounded top.
  EXPECT_LT(cu.profile.bottom_ramp, cu.profile.top_ramp);
  EXPECT_FALSE(cu.stratiform);
  // Cumulonimbus: deep, towering (noise stretched vertically more than cumulus), large droplets.
  EXPECT_GE(cb.default_top_m, 10000.0);
  EXPECT_LT(cb.noise_vertical_scale, cu.noise_vertical_scale);
  EXPECT_LT(cu.noise_vertical_scale, st.noise_vertical_scale);
  EXPECT_GT(cb.default_droplet_diameter_um, cu.default_droplet_diameter_um);
  // Ice clouds: high and optically thin.
  for (CloudType t : {CloudType::Cirrus, CloudType::Cirrostratus, CloudType::Cirrocumulus}) {
    EXPECT_GE(cloud_type_traits(t).default_base_m, 6000.0) << cloud_type_name(t);
    EXPECT_LT(cloud_type_traits(t).default_density_scale, 0.01) << cloud_type_name(t);
  }
  EXPECT_GT(ci.default_base_m, cb.default_base_m);
}

// Highest height fraction (0.001 resolution) where the profile is non-zero.
float cloud_top_fraction(const HeightProfile& p, bool stratiform, float t) {
  float top = 0.0f;
  for (int i = 1; i < 1000; ++i) {
    const float f = i / 1000.0f;
    if (type_height_profile(p, stratiform, f, t) > 0.0f) top = f;
  }
  return top;
}

// The weather map's cloud-type channel t (G) selects the height profile of a convective
// layer: t = 0 puts the cell tops at half the layer, t = 0.25 at three quarters, t >= 0.5
// (neutral) uses the whole layer; the profile is the type's own, scaled into f_v(t).
TEST(CloudTypeChannel, SelectsTheHeightProfileOfConvectiveLayers) {
  for (CloudType type : {CloudType::Cumulus, CloudType::Cumulonimbus}) {
    SCOPED_TRACE(std::string(cloud_type_name(type)));
    const CloudTypeTraits& tr = cloud_type_traits(type);
    ASSERT_FALSE(tr.stratiform);
    EXPECT_FLOAT_EQ(type_depth_fraction(0.0f, false), 0.5f);
    EXPECT_FLOAT_EQ(type_depth_fraction(0.25f, false), 0.75f);
    EXPECT_FLOAT_EQ(type_depth_fraction(0.5f, false), 1.0f);
    EXPECT_FLOAT_EQ(type_depth_fraction(1.0f, false), 1.0f);
    EXPECT_NEAR(cloud_top_fraction(tr.profile, false, 0.0f), 0.5f, 0.002f);
    EXPECT_NEAR(cloud_top_fraction(tr.profile, false, 0.25f), 0.75f, 0.002f);
    EXPECT_NEAR(cloud_top_fraction(tr.profile, false, 0.5f), 1.0f, 0.002f);
    // Cell tops rise monotonically with t up to the neutral value, then stay.
    float previous = 0.0f;
    for (float t = 0.0f; t <= 1.0f; t += 0.05f) {
      const float top = cloud_top_fraction(tr.profile, false, t);
      EXPECT_GE(top, previous) << "t " << t;
      previous = top;
    }
    // The type's own shape, compressed: the profile at f under t equals the full profile
    // at f / f_v(t) (same base ramp, rounded top at the lower top).
    for (float t : {0.0f, 0.2f, 0.4f}) {
      const float fv = type_depth_fraction(t, false);
      for (float x : {0.02f, 0.1f, 0.3f, 0.6f, 0.9f, 0.98f})
        EXPECT_NEAR(type_height_profile(tr.profile, false, x * fv, t), height_profile(tr.profile, x), 1e-5)
            << "t " << t << " x " << x;  // x * fv / fv rounds in float
    }
    // Neutral and above: the layer as specified.
    for (float f : {0.05f, 0.5f, 0.95f})
      for (float t : {0.5f, 0.75f, 1.0f})
        EXPECT_FLOAT_EQ(type_height_profile(tr.profile, false, f, t), height_profile(tr.profile, f));
    // A low-development cell has no density in the upper half of the layer.
    EXPECT_EQ(type_height_profile(tr.profile, false, 0.7f, 0.0f), 0.0f);
    EXPECT_GT(type_height_profile(tr.profile, false, 0.7f, 0.5f), 0.0f);
  }
  // Non-finite t is the neutral value.
  EXPECT_FLOAT_EQ(type_depth_fraction(std::nanf(""), false), 1.0f);
}

TEST(CloudTypeChannel, StratiformLayersIgnoreIt) {
  for (CloudType type : all_cloud_types()) {
    const CloudTypeTraits& tr = cloud_type_traits(type);
    if (!tr.stratiform) continue;
    SCOPED_TRACE(std::string(cloud_type_name(type)));
    for (float t : {0.0f, 0.25f, 0.5f, 1.0f}) {
      EXPECT_FLOAT_EQ(type_depth_fraction(t, true), 1.0f);
      for (float f : {0.05f, 0.4f, 0.7f, 0.95f})
        EXPECT_FLOAT_EQ(type_height_profile(tr.profile, true, f, t), height_profile(tr.profile, f));
    }
  }
}

// height_profile is the shader's formula: ramps at base and top, zero outside the layer.
TEST(CloudTypeChannel, HeightProfileFormula) {
  const HeightProfile cu = cloud_type_traits(CloudType::Cumulus).profile;  // 0.05 / 0.6 / 0
  EXPECT_EQ(height_profile(cu, 0.0f), 0.0f);
  EXPECT_EQ(height_profile(cu, 1.0f), 0.0f);
  EXPECT_EQ(height_profile(cu, -0.1f), 0.0f);
  EXPECT_FLOAT_EQ(height_profile(cu, 0.2f), 1.0f);     // above the base ramp, below the top ramp
  EXPECT_FLOAT_EQ(height_profile(cu, 0.025f), 0.5f);   // middle of the base ramp
  EXPECT_FLOAT_EQ(height_profile(cu, 0.7f), 1.0f - 0.5f);  // middle of the top ramp (0.4..1)
  HeightProfile anvil = cu;
  anvil.top_weight = 1.0f;
  EXPECT_FLOAT_EQ(height_profile(anvil, 0.2f), 0.2f);  // grows linearly with height
}

TEST(Validate, AcceptsEmptyAndTouchingLayers) {
  EXPECT_EQ(validate(Weather{}), "");
  Weather w = one_layer(cumulus());
  CloudLayer upper = default_layer(CloudType::Altostratus);
  upper.base_m = 2000;  // touches the cumulus top
  upper.top_m = 3000;
  w.layers.push_back(upper);
  EXPECT_EQ(validate(w), "");
}

TEST(Validate, MessageFormat) {
  Weather w = one_layer(cumulus());
  CloudLayer second = cumulus();
  second.base_m = 3000;
  second.top_m = 4000;
  second.coverage = 1.5;
  w.layers.push_back(second);
  EXPECT_EQ(validate(w), "layers[1].coverage 1.5 out of range [0, 1]");
  const auto issue = validate_detail(w);
  ASSERT_TRUE(issue.has_value());
  EXPECT_EQ(issue->field, "layers[1].coverage");
  EXPECT_EQ(issue->problem, "1.5 out of range [0, 1]");
}

// Each case: a mutation of a valid cumulus layer and the field the message must name.
struct BadLayerCase {
  const char* name;
  void (*mutate)(CloudLayer&);
  const char* field;
};

TEST(Validate, NamesTheOffendingField) {
  const BadLayerCase cases[] = {
      {"type none", [](CloudLayer& l) { l.type = CloudType::None; }, "layers[0].type"},
      {"type 42", [](CloudLayer& l) { l.type = static_cast<CloudType>(42); }, "layers[0].type"},
      {"base nan", [](CloudLayer& l) { l.base_m = kNaN; }, "layers[0].base_m"},
      {"base low", [](CloudLayer& l) { l.base_m = -600; }, "layers[0].base_m"},
      {"top nan", [](CloudLayer& l) { l.top_m = kNaN; }, "layers[0].top_m"},
      {"top below base", [](CloudLayer& l) { l.top_m = 900; }, "layers[0].top_m"},
      {"top equal base", [](CloudLayer& l) { l.top_m = 1000; }, "layers[0].top_m"},
      {"too thin", [](CloudLayer& l) { l.top_m = 1005; }, "layers[0].top_m"},
      {"top high", [](CloudLayer& l) { l.top_m = 20001; }, "layers[0].top_m"},
      {"coverage neg", [](CloudLayer& l) { l.coverage = -0.1; }, "layers[0].coverage"},
      {"coverage inf", [](CloudLayer& l) { l.coverage = INFINITY; }, "layers[0].coverage"},
      {"density", [](CloudLayer& l) { l.density_scale = 11; }, "layers[0].density_scale"},
      {"droplet small", [](CloudLayer& l) { l.droplet_diameter_um = 4; },
       "layers[0].droplet_diameter_um"},
      {"droplet 60", [](CloudLayer& l) { l.droplet_diameter_um = 60; },
       "layers[0].droplet_diameter_um"},
      {"wind nan", [](CloudLayer& l) { l.wind.north_mps = kNaN; }, "layers[0].wind_mps"},
      {"wind fast", [](CloudLayer& l) { l.wind = {120, 100}; }, "layers[0].wind_mps"},
  };
  for (const BadLayerCase& c : cases) {
    CloudLayer l = cumulus();
    c.mutate(l);
    const std::string msg = validate(one_layer(l));
    EXPECT_EQ(msg.rfind(std::string(c.field) + " ", 0), 0u) << c.name << ": " << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << c.name;
  }
  // Boundaries are inclusive.
  CloudLayer edge = cumulus();
  edge.base_m = -500;
  edge.top_m = 20000;
  edge.coverage = 1.0;
  edge.density_scale = 10;
  edge.droplet_diameter_um = 50;
  edge.wind = {90, 120};  // exactly 150 m/s
  EXPECT_EQ(validate(one_layer(edge)), "");
}

TEST(Validate, TooManyLayers) {
  Weather w;
  for (int i = 0; i < kMaxCloudLayers + 1; ++i) {
    CloudLayer l = cumulus();
    l.base_m = 1000.0 * (i + 1);
    l.top_m = l.base_m + 500;
    w.layers.push_back(l);
  }
  EXPECT_EQ(validate(w), "layers 5 layers, at most 4 allowed");
  w.layers.pop_back();
  EXPECT_EQ(validate(w), "");
}

TEST(Validate, OverlapNamesThePair) {
  Weather w = one_layer(cumulus());  // 1000-2000
  CloudLayer upper = cumulus();
  upper.base_m = 1500;
  upper.top_m = 2500;
  w.layers.push_back(upper);
  const std::string msg = validate(w);
  EXPECT_NE(msg.find("layers[1]"), std::string::npos) << msg;
  EXPECT_NE(msg.find("overlaps layers[0]"), std::string::npos) << msg;
}

TEST(Validate, UnsortedLayers) {
  CloudLayer upper = cumulus();
  upper.base_m = 3000;
  upper.top_m = 4000;
  Weather w = one_layer(upper);
  w.layers.push_back(cumulus());
  const std::string msg = validate(w);
  EXPECT_EQ(msg.rfind("layers[1].base_m ", 0), 0u) << msg;
  EXPECT_NE(msg.find("sorted"), std::string::npos) << msg;
}

}  // namespace
}  // namespace cloudsvc::weather
