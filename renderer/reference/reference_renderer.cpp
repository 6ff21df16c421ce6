// Frame loop of the reference renderer (see reference_renderer.h).
#include "renderer/reference/reference_renderer.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "common/parallel_for.h"
#include "renderer/reference/cloud_field.h"
#include "renderer/reference/pixel_integrator.h"
#include "renderer/reference/reference_scene.h"

namespace cloudsvc::reference {

FrameImage render_reference(const ViewRequest& view, const weather::Weather& weather,
                            const ReferenceSettings& settings, const WindAnchor* wind_anchor) {
  if (view.width <= 0 || view.height <= 0) throw std::invalid_argument("render_reference: empty image size");
  if (!(settings.cloud_step_m > 0.0) || !(settings.light_step_m > 0.0) || !(settings.atmosphere_step_m > 0.0))
    throw std::invalid_argument("render_reference: steps must be positive");
  if (settings.pixel_samples < 1 || settings.pixel_samples > 16)
    throw std::invalid_argument("render_reference: pixel_samples must be 1..16");
  const auto start = std::chrono::steady_clock::now();

  const ReferenceScene scene = make_reference_scene(view, weather, wind_anchor, settings.cloud_phase);
  AtmosphereTableSettings table_settings = settings.tables;
  table_settings.threads = settings.threads;
  table_settings.aerosol_scale = scene.aerosol_scale;
  const std::shared_ptr<const AtmosphereTables> tables = atmosphere_tables(table_settings);
  // The noise volumes and the weather map are only read inside cloud layers: a clear sky
  // does not need them (saves ~1-2 s of generation in a fresh process).
  static const std::shared_ptr<const ReferenceInputs> no_inputs = std::make_shared<const ReferenceInputs>();
  const std::shared_ptr<const ReferenceInputs> inputs =
      weather.layers.empty() ? no_inputs : reference_inputs(settings.inputs, weather.map_seed);

  const CloudField field(scene, *inputs, settings.honour_stratiform, settings.cumulus_domes, settings.noise_tiling);
  const PixelIntegrator integrator(field, *tables, settings);

  FrameImage img;
  img.width = view.width;
  img.height = view.height;
  img.rgba.assign(static_cast<std::size_t>(view.width) * view.height * 4, 0.0f);
  std::vector<std::uint64_t> row_evals(static_cast<std::size_t>(view.height), 0);
  std::vector<int> row_nonfinite(static_cast<std::size_t>(view.height), 0);
  std::vector<int> row_cloud(static_cast<std::size_t>(view.height), 0);

  parallel_for(view.height, settings.threads, [&](int y) {
    std::uint64_t evals = 0;
    for (int x = 0; x < view.width; ++x) {
      const int n = settings.pixel_samples;
      glm::dvec3 rgb(0.0);
      double opacity = 0.0;
      bool bad = false;  // any sub-sample NaN/Inf/negative (an average would hide a negative one)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const PixelRadiance px =
              integrator.shade(scene.camera.ray_at(x + (i + 0.5) / n, y + (j + 0.5) / n), evals);
          for (int c = 0; c < 3; ++c) bad |= !std::isfinite(px.radiance[c]) || px.radiance[c] < 0.0;
          bad |= !std::isfinite(px.opacity);
          rgb += px.radiance;
          opacity += px.opacity;
        }
      rgb /= static_cast<double>(n * n);
      opacity /= static_cast<double>(n * n);
      if (bad) {
        ++row_nonfinite[static_cast<std::size_t>(y)];
        rgb = glm::dvec3(0.0);
      }
      const double alpha = bad ? 0.0 : opacity;
      if (alpha > kCloudPixelOpacity) ++row_cloud[static_cast<std::size_t>(y)];
      float* out = &img.rgba[(static_cast<std::size_t>(y) * view.width + x) * 4];
      out[0] = static_cast<float>(rgb.r);
      out[1] = static_cast<float>(rgb.g);
      out[2] = static_cast<float>(rgb.b);
      out[3] = static_cast<float>(alpha);
    }
    row_evals[static_cast<std::size_t>(y)] = evals;
  });

  std::uint64_t evals = 0;
  for (int y = 0; y < view.height; ++y) {
    evals += row_evals[static_cast<std::size_t>(y)];
    img.stats.nonfinite_pixels += row_nonfinite[static_cast<std::size_t>(y)];
    img.stats.cloud_pixels += row_cloud[static_cast<std::size_t>(y)];
  }
  img.stats.density_evals_per_pixel = static_cast<double>(evals) / (static_cast<double>(view.width) * view.height);
  img.stats.sun_elevation_deg = scene.sun_elevation_deg;
  img.stats.sun_azimuth_deg = scene.sun_azimuth_deg;
  img.stats.render_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return img;
}

}  // namespace cloudsvc::reference
