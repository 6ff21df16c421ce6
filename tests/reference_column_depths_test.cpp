// The column depths' quadrature (CloudField::column_depths, the GPU's
// marched_column_depths in shaders/column_quadrature.glsl): the exact mean of the clamped
// ramp, and the column depths of cumulus, stratocumulus, stratus and cumulonimbus layers
// against the field's own integral (a 1 m midpoint rule over CloudField::sample), at the
// reference's node spacing and at the GPU's 8 steps per column.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "renderer/reference/cloud_field.h"
#include "renderer/reference/cloud_lighting.h"
#include "renderer/reference/reference_renderer.h"
#include "renderer/reference/reference_scene.h"

namespace cloudsvc::reference {
namespace {

double numeric_saturate_mean(double a, double b) {
  const int n = 200000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += std::clamp(a + (b - a) * (i + 0.5) / n, 0.0, 1.0);
  return sum / n;
}

TEST(ColumnQuadrature, SaturateMeanIsTheExactMeanOfTheClampedRamp) {
  for (const auto& [a, b] : {std::pair{-2.0, -1.0}, {-1.0, 0.5}, {0.2, 0.7}, {0.7, 0.2}, {-0.5, 1.5}, {1.5, -0.5},
                             {0.9, 3.0}, {2.0, 4.0}, {0.3, 0.3}, {0.3, 0.3 + 1e-9}, {-3.0, 5.0}}) {
    EXPECT_NEAR(CloudField::saturate_mean(a, b), numeric_saturate_mean(a, b), 1e-6) << a << " .. " << b;
  }
  // a ramp from -1 to 3: 1/4 of it below 0 (0), 1/4 on [0, 1] (mean 1/2), 1/2 above (1)
  EXPECT_NEAR(CloudField::saturate_mean(-1.0, 3.0), 0.625, 1e-12);
}

ViewRequest level_view(double alt) {
  ViewRequest v;
  v.position = {47.45, 8.0, alt};
  v.attitude = {90.0, 0.0, 0.0};
  v.unix_time_s = 1.78e9;
  v.width = 64;
  v.height = 36;
  v.fov_deg = 90.0;
  return v;
}

struct LayerCase {
  weather::CloudType type;
  double base_m, top_m, coverage;
  double max_error_reference;  // mean |dT/T| at the reference's node spacing (ReferenceSettings)
  double max_error_gpu;        // ... at 8 steps per column (the presets' column_steps)
  double max_error_gpu_top;    // ... of the depths at samples in the top fifth of the profile
  const char* name;
};

// The diffuse transmittance 1 / (1 + 0.105 tau) of a depth tau (a conservative slab's,
// (1 - g) tau / 2 with g = 0.79): how much a depth's error matters to the diffuse light.
double diffuse_transmittance(double tau) { return 1.0 / (1.0 + 0.105 * tau); }

// Over 300 in-cloud points of a layer: the depths above and below each point, from the
// quadrature with the reference's node spacing and with the GPU's 8 steps per column,
// against the field's own integral with 1 m steps.
TEST(ColumnQuadrature, ColumnDepthsConvergeToTheFieldsIntegral) {
  const LayerCase cases[] = {
      {weather::CloudType::Cumulus, 1200.0, 2400.0, 0.45, 0.005, 0.02, 0.02, "cumulus"},
      {weather::CloudType::Stratocumulus, 1200.0, 1900.0, 0.9, 0.005, 0.005, 0.005, "stratocumulus"},
      {weather::CloudType::Stratus, 400.0, 1200.0, 1.0, 0.005, 0.015, 0.015, "stratus"},
      // the anvil's ramps need pieces of their own (CloudField::column_pieces): 0.10 in the
      // top fifth with 4 per step
      {weather::CloudType::Cumulonimbus, 1000.0, 11000.0, 0.5, 0.005, 0.05, 0.06, "cumulonimbus"},
  };
  for (const LayerCase& c : cases) {
    weather::Weather w;
    weather::CloudLayer l = weather::default_layer(c.type);
    l.base_m = c.base_m;
    l.top_m = c.top_m;
    l.coverage = c.coverage;
    w.layers.push_back(l);
    w.map_seed = 11;
    const ReferenceScene s = make_reference_scene(level_view(200.0), w);
    const auto inputs = reference_inputs(InputConfig{}, w.map_seed);
    const CloudField field(s, *inputs);
    const ReferenceSettings settings;
    const double reference_spacing = settings.light_step_m * layer_step_scale(s.layers[0]) * settings.column_step_factor;
    std::uint64_t evals = 0;
    double err_ref = 0.0, err_gpu = 0.0, err_gpu_top = 0.0;
    int n = 0, n_top = 0;
    for (int i = 0; n < 300 && i < 20000; ++i) {
      // points on a lattice of columns 173 m apart, at heights through the layer
      const glm::dvec3 ground(173.0 * (i % 97), 173.0 * (i / 97), 0.0);
      const glm::dvec3 up = s.shell.up_at(ground);
      const double h = c.base_m + (c.top_m - c.base_m) * ((i * 0.618034) - std::floor(i * 0.618034));
      const glm::dvec3 p = ground + up * (h - s.shell.altitude_of(ground));
      const double alt = s.shell.altitude_of(p);
      if (field.sample(0, p, alt, false, evals).sigma_t <= 0.0) continue;  // lit samples are in cloud
      ++n;
      const double top = field.profile_top_m(0, p);
      const glm::dvec2 ref_depths = field.column_depths(  // (below, above)
          0, p, alt, [&](double len) { return std::max(1, static_cast<int>(std::ceil(len / reference_spacing))); },
          evals);
      // the GPU's share of 8 steps for each part of the column (marched_column_depths,
      // shaders/column_quadrature.glsl)
      const glm::dvec2 gpu_depths = field.column_depths(
          0, p, alt, [&](double len) { return std::max(1, static_cast<int>(std::ceil(8.0 * len / (top - c.base_m)))); },
          evals);
      for (const int part : {1, 0}) {
        const double len = part == 1 ? top - alt : -(alt - c.base_m);
        if (std::abs(len) < 1.0) continue;
        // the field's own integral, 1 m midpoint steps
        const int fine_steps = static_cast<int>(std::ceil(std::abs(len)));
        double tau = 0.0;
        for (int j = 0; j < fine_steps; ++j) {
          const double ds = len / fine_steps, t = (j + 0.5) * ds;
          tau += field.sample(0, p + up * t, alt + t, false, evals).sigma_t * std::abs(ds);
        }
        const double tau_ref = ref_depths[part], tau_gpu = gpu_depths[part];
        const double t = diffuse_transmittance(tau);
        err_ref += std::abs(diffuse_transmittance(tau_ref) / t - 1.0);
        err_gpu += std::abs(diffuse_transmittance(tau_gpu) / t - 1.0);
        if (top - alt < 0.2 * (top - c.base_m)) {  // the top fifth: what a view from above sees
          err_gpu_top += std::abs(diffuse_transmittance(tau_gpu) / t - 1.0);
          ++n_top;
        }
      }
    }
    ASSERT_EQ(n, 300) << c.name << ": too few in-cloud points";
    err_ref /= 2 * n;
    err_gpu /= 2 * n;
    err_gpu_top /= std::max(n_top, 1);
    std::printf("%-14s mean |dT/T| of the column depths: reference spacing (%.0f m) %.4f, GPU 8 steps %.4f (top fifth "
                "%.4f over %d depths)\n", c.name, reference_spacing, err_ref, err_gpu, err_gpu_top, n_top);
    EXPECT_LT(err_ref, c.max_error_reference) << c.name;
    EXPECT_LT(err_gpu, c.max_error_gpu) << c.name;
    if (n_top >= 20) {  // cumulus: no in-cloud points that high
      EXPECT_LT(err_gpu_top, c.max_error_gpu_top) << c.name;
    }
  }
}

}  // namespace
}  // namespace cloudsvc::reference
