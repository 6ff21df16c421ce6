// Frame loop of the ground truth (see truth_renderer.h).
#include "renderer/truth/truth_renderer.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <algorithm>
#include <vector>

#include "common/parallel_for.h"
#include "renderer/reference/cloud_field.h"
#include "renderer/reference/reference_scene.h"
#include "renderer/truth/scene_world.h"

namespace cloudsvc::truth {

TruthImage render_truth(const ViewRequest& view, const weather::Weather& weather, const TruthSettings& settings,
                        const WindAnchor* wind_anchor) {
  if (view.width <= 0 || view.height <= 0) throw std::invalid_argument("render_truth: empty image size");
  if (settings.spp < 2) throw std::invalid_argument("render_truth: spp must be at least 2 (for the standard error)");
  const auto start = std::chrono::steady_clock::now();

  static const std::shared_ptr<const reference::ReferenceInputs> no_inputs =
      std::make_shared<const reference::ReferenceInputs>();
  const std::shared_ptr<const reference::ReferenceInputs> inputs =
      weather.layers.empty() ? no_inputs : reference::reference_inputs(settings.inputs, weather.map_seed);
  const reference::ReferenceScene scene = reference::make_reference_scene(view, weather, wind_anchor, settings.cloud_phase);
  const reference::CloudField field(scene, *inputs, settings.honour_stratiform, false, settings.noise_tiling);
  const SceneMedium medium(scene, field);
  const SceneLocalMajorant local(scene, *inputs, settings.honour_stratiform, scene_band_edges(scene),
                                 settings.noise_tiling);
  const TruthWorld world = make_scene_world(scene, *inputs, settings.honour_stratiform, medium,
                                            scene.layers.empty() ? nullptr : &local);
  const glm::dvec3 camera(0.0, 0.0, scene.shell.radius_m + scene.shell.camera_alt_m);  // centred frame

  const int pixels = view.width * view.height;
  TruthImage out;
  out.spp = settings.spp;
  FrameImage& img = out.image;
  img.width = view.width;
  img.height = view.height;
  img.rgba.assign(static_cast<std::size_t>(pixels) * 4, 0.0f);
  img.std_error.assign(static_cast<std::size_t>(pixels) * 3, 0.0f);
  out.incomplete.assign(static_cast<std::size_t>(pixels), 0);
  std::vector<TracerCounters> pixel_counters(static_cast<std::size_t>(pixels));
  std::vector<char> pixel_bad(static_cast<std::size_t>(pixels), 0);

  const SunDepthCache sun_depth = make_sun_depth_cache(world, settings.tracer);
  parallel_for(pixels, settings.threads, [&](int i) {
    const int x = i % view.width, y = i / view.width;
    model::Pcg32 rng = model::chunk_stream(settings.seed, static_cast<std::uint64_t>(i));
    TracerCounters& counters = pixel_counters[static_cast<std::size_t>(i)];
    PathTracer tracer(world, settings.tracer, sun_depth, rng, counters);
    glm::dvec3 sum(0.0), sum2(0.0);
    double transmittance = 0.0;
    bool bad = false;
    int done = 0;
    for (int s = 0; s < settings.spp; ++s) {
      const std::uint64_t lost_before = counters.lost_paths;
      const double px = x + rng.uniform(), py = y + rng.uniform();
      const glm::dvec3 dir = scene.camera.ray_at(px, py);
      const glm::dvec3 L = tracer.radiance(camera, dir);
      if (counters.lost_paths != lost_before) {
        out.incomplete[static_cast<std::size_t>(i)] = 1;
        break;
      }
      for (int c = 0; c < 3; ++c) bad |= !std::isfinite(L[c]) || L[c] < 0.0;
      sum += L;
      sum2 += L * L;
      transmittance += tracer.cloud_transmittance(camera, dir);
      ++done;
    }
    const double n = std::max(done, 2);
    const glm::dvec3 mean = sum / n;
    const glm::dvec3 var = glm::max(glm::dvec3(0.0), (sum2 - n * mean * mean) / (n - 1.0));
    const glm::dvec3 se = glm::sqrt(var / n);
    const double opacity = std::clamp(1.0 - transmittance / n, 0.0, 1.0);
    bad |= !std::isfinite(opacity) || !std::isfinite(se.r + se.g + se.b);
    pixel_bad[static_cast<std::size_t>(i)] = bad ? 1 : 0;
    float* rgba = &img.rgba[static_cast<std::size_t>(i) * 4];
    float* e = &img.std_error[static_cast<std::size_t>(i) * 3];
    for (int c = 0; c < 3; ++c) {
      rgba[c] = bad ? 0.0f : static_cast<float>(mean[c]);
      e[c] = bad ? 0.0f : static_cast<float>(se[c]);
    }
    rgba[3] = bad ? 0.0f : static_cast<float>(opacity);
  });

  for (int i = 0; i < pixels; ++i) {
    out.counters.add(pixel_counters[static_cast<std::size_t>(i)]);
    img.stats.nonfinite_pixels += pixel_bad[static_cast<std::size_t>(i)];
    out.incomplete_pixels += out.incomplete[static_cast<std::size_t>(i)];
    if (img.rgba[static_cast<std::size_t>(i) * 4 + 3] > 0.01f) ++img.stats.cloud_pixels;
  }
  out.sun_depth_cells = sun_depth.cells();
  out.sun_depth_evals = sun_depth.density_evals();
  const std::uint64_t evals = out.counters.density_evals + out.sun_depth_evals;
  img.stats.density_evals_per_pixel = static_cast<double>(evals) / pixels;
  img.stats.sun_elevation_deg = scene.sun_elevation_deg;
  img.stats.sun_azimuth_deg = scene.sun_azimuth_deg;
  img.stats.render_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace cloudsvc::truth
