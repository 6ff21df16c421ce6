// The textured base of stratus and nimbostratus (CloudTypeTraits::base_relief, step 5 of
// renderer/reference/cloud_field.h): measured on the CPU reference's field, the cloud base
// over a grid of vertical columns is where a climbing aircraft's visibility first falls
// below 1 km (extinction 3.912 / 1000 m, Koschmieder; the WMO's cloud/fog visibility
// threshold). With the relief the base is lumpy at the detail noise's scale (hundreds of
// metres), where the same layer without it is flat to a few metres; layers of other types
// keep their flat base.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "renderer/reference/cloud_field.h"
#include "renderer/reference/reference_renderer.h"
#include "renderer/reference/reference_scene.h"
#include "tests/make_view.h"

namespace cloudsvc::reference {
namespace {

constexpr double kVisibility1kmExtinction = 3.912e-3;  // 1/m: visibility 1 km (Koschmieder)

struct BaseStatistics {
  double mean_m = 0.0, sd_m = 0.0, min_m = 0.0, p10_m = 0.0, p90_m = 0.0, max_m = 0.0;  // above the layer's base
  double half_length_m = 0.0;  // lag at which the base height's autocorrelation falls below 1/2, east-west
  int columns = 0;             // columns with a base below the scan's top
};

// The cloud base of layer 0 over n x n columns `spacing` apart centred under the camera:
// scanned upwards from the layer's base in steps of `step` m over the lower `scan_fraction`
// of its depth (detail on, as a view ray sees it).
BaseStatistics base_statistics(const ReferenceScene& s, const ReferenceInputs& inputs, int n, double spacing,
                               double step, double scan_fraction) {
  const CloudField field(s, inputs);
  const ReferenceLayer& L = s.layers[0];
  const double depth = L.top_m - L.base_m;
  const int levels = static_cast<int>(scan_fraction * depth / step);
  std::vector<double> base(static_cast<size_t>(n) * n, std::nan(""));
  std::uint64_t evals = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::dvec3 ground(spacing * (i - 0.5 * n), spacing * (j - 0.5 * n), 0.0);
      const glm::dvec3 up = s.shell.up_at(ground);
      const double ground_alt = s.shell.altitude_of(ground);
      for (int k = 1; k <= levels; ++k) {
        const double h = k * step;
        const glm::dvec3 p = ground + up * (L.base_m + h - ground_alt);
        if (field.sample(0, p, s.shell.altitude_of(p), true, evals).sigma_t >= kVisibility1kmExtinction) {
          base[static_cast<size_t>(j) * n + i] = h;
          break;
        }
      }
    }
  BaseStatistics b;
  std::vector<double> found;
  for (double h : base)
    if (std::isfinite(h)) found.push_back(h);
  b.columns = static_cast<int>(found.size());
  if (found.empty()) return b;
  for (double h : found) b.mean_m += h;
  b.mean_m /= found.size();
  for (double h : found) b.sd_m += (h - b.mean_m) * (h - b.mean_m);
  b.sd_m = std::sqrt(b.sd_m / found.size());
  std::sort(found.begin(), found.end());
  b.min_m = found.front();
  b.p10_m = found[found.size() / 10];
  b.p90_m = found[found.size() * 9 / 10];
  b.max_m = found.back();
  // autocorrelation along rows (east-west) over the columns with a base at both ends
  double prev = 1.0;
  b.half_length_m = spacing * n / 2.0;
  for (int lag = 1; lag < n / 2; ++lag) {
    double c = 0.0, var = 0.0;
    int m = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i + lag < n; ++i) {
        const double h0 = base[static_cast<size_t>(j) * n + i], h1 = base[static_cast<size_t>(j) * n + i + lag];
        if (!std::isfinite(h0) || !std::isfinite(h1)) continue;
        c += (h0 - b.mean_m) * (h1 - b.mean_m);
        var += 0.5 * ((h0 - b.mean_m) * (h0 - b.mean_m) + (h1 - b.mean_m) * (h1 - b.mean_m));
        ++m;
      }
    const double r = var > 0.0 ? c / var : 0.0;
    if (r < 0.5) {
      b.half_length_m = spacing * (lag - (0.5 - r) / (prev - r));
      break;
    }
    prev = r;
  }
  return b;
}

struct ReliefCase {
  weather::CloudType type;
  double base_m, top_m, coverage;
  double min_sd_m;          // the base's standard deviation with the relief, at least
  double min_half_length_m, max_half_length_m;  // its lumps: neither a grain nor one slope
};

class TexturedBase : public ::testing::TestWithParam<ReliefCase> {};

TEST_P(TexturedBase, TheBaseIsLumpyWithTheReliefAndFlatWithout) {
  const ReliefCase c = GetParam();
  weather::Weather w;
  weather::CloudLayer l;
  l.type = c.type;
  l.base_m = c.base_m;
  l.top_m = c.top_m;
  l.coverage = c.coverage;
  l.density_scale = weather::cloud_type_traits(c.type).default_density_scale;
  w.layers.push_back(l);
  w.map_seed = 4;
  const ViewRequest v = test::make_view(47.45, 8.56, 100.0, 0.0, 90.0, "2026-06-21T11:30:00Z", 16, 9);
  const ReferenceScene textured = make_reference_scene(v, w);
  ReferenceScene flat = textured;
  flat.layers[0].base_relief = 0.0;
  const auto inputs = reference_inputs(InputConfig{}, w.map_seed);
  const double relief = weather::cloud_type_traits(c.type).base_relief;
  const double depth = c.top_m - c.base_m;
  ASSERT_GT(relief, 0.0) << "the type has a textured base";
  ASSERT_EQ(textured.layers[0].base_relief, relief);
  const double step = std::max(2.0, depth / 400.0), scan = relief + 0.3;
  const BaseStatistics t = base_statistics(textured, *inputs, 48, 100.0, step, scan);
  const BaseStatistics f = base_statistics(flat, *inputs, 48, 100.0, step, scan);
  const std::string name(weather::cloud_type_name(c.type));
  for (const auto& [label, b] : {std::pair{"textured", t}, std::pair{"flat", f}})
    std::printf("%s %s: base above the layer's %.0f m: mean %.1f m, sd %.1f m, min %.0f m, p10 %.0f m, p90 %.0f m, max %.0f m; "
                "half-length east-west %.0f m; %d of %d columns\n",
                name.c_str(), label, c.base_m, b.mean_m, b.sd_m, b.min_m, b.p10_m, b.p90_m, b.max_m, b.half_length_m, b.columns,
                48 * 48);
  EXPECT_EQ(t.columns, 48 * 48) << "every column of the sheet has a base within the scan";
  EXPECT_EQ(f.columns, 48 * 48);
  EXPECT_GT(t.sd_m, c.min_sd_m);
  EXPECT_GT(t.sd_m, 3.0 * f.sd_m) << "the relief, not the ramp, makes the base's texture";
  EXPECT_GT(t.half_length_m, c.min_half_length_m);
  EXPECT_LT(t.half_length_m, c.max_half_length_m);
  // the base rises by at most the relief plus the bottom ramp, and not all of it
  EXPECT_LE(t.max_m, (relief + textured.layers[0].bottom_ramp) * depth + step);
  // the lowest bases stay at the layer's base (the ceiling the weather gives)
  EXPECT_LE(t.min_m, f.max_m + 0.1 * relief * depth);
  EXPECT_GT(t.mean_m, f.mean_m);
  EXPECT_LT(t.mean_m - f.mean_m, relief * depth);
}

INSTANTIATE_TEST_SUITE_P(Sheets, TexturedBase,
                         ::testing::Values(ReliefCase{weather::CloudType::Stratus, 400.0, 900.0, 1.0, 15.0, 100.0, 1500.0},
                                           ReliefCase{weather::CloudType::Nimbostratus, 600.0, 4000.0, 1.0, 25.0, 150.0,
                                                      2000.0}),
                         [](const ::testing::TestParamInfo<ReliefCase>& info) {
                           return std::string(weather::cloud_type_name(info.param.type));
                         });

TEST(TexturedBase, OnlyStratusAndNimbostratusHaveOne) {
  for (const weather::CloudType t : weather::all_cloud_types()) {
    const double r = weather::cloud_type_traits(t).base_relief;
    if (t == weather::CloudType::Stratus || t == weather::CloudType::Nimbostratus)
      EXPECT_GT(r, 0.0) << weather::cloud_type_name(t);
    else
      EXPECT_EQ(r, 0.0) << weather::cloud_type_name(t);
  }
}

}  // namespace
}  // namespace cloudsvc::reference
