// Where the ground truth spends its paths on one benchmark scene: renders the truth of scene
// i of a scene set (bench/bench_scenes.h) and prints its cost and noise: seconds, density
// evaluations per pixel, tentative collisions / real scatterings / sun-guided copies per
// camera path, incomplete pixels, and the relative noise over cloud pixels that
// cloudbench --truth uses to decide whether a scene is resolved, and which kinds of
// contribution (truth::Contribution) carry the estimate and its second moment. Flags override the tracer's
// settings so that estimator changes can be compared on the scenes that need them.
//
// Usage: truth_scene_probe [--scenes random:2026:32] [--scene 8] [--size 16x9] [--spp 32]
//          [--max-collisions 20000] [--guiding 0.3] [--max-copies 64] [--twilight-floor 2e-4] [--seed 1]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include <CLI/CLI.hpp>

#include "bench/bench_scenes.h"
#include "bench/bench_util.h"
#include "bench/truth_command.h"
#include "renderer/reference/reference_scene.h"
#include "renderer/truth/truth_renderer.h"

int main(int argc, char** argv) {
  using namespace cloudsvc;
  CLI::App app{"Cost and noise of the path-traced truth on one benchmark scene"};
  std::string scenes_text = "random:2026:32", size = "16x9";
  int index = 0;
  truth::TruthSettings settings;
  settings.spp = 32;
  settings.tracer.max_collisions = 20000;
  app.add_option("--scenes", scenes_text, "core or random:SEED:N");
  app.add_option("--scene", index, "index of the scene in the set")->check(CLI::NonNegativeNumber);
  app.add_option("--size", size, "image size WxH");
  app.add_option("--spp", settings.spp, "paths per pixel")->check(CLI::Range(2, 1 << 20));
  app.add_option("--seed", settings.seed, "random seed");
  app.add_option("--max-collisions", settings.tracer.max_collisions, "tentative collisions per camera path (with its copies)");
  app.add_option("--guiding", settings.tracer.sun_guiding, "probability of a sun-guided copy")->check(CLI::Range(0.0, 0.99));
  app.add_option("--max-copies", settings.tracer.max_copies, "copies per camera path")->check(CLI::NonNegativeNumber);
  app.add_option("--guide-depth", settings.tracer.guide_depth,
                 "copies only where the cloud optical depth towards the sun is below this (inf = anywhere)")
      ->check(CLI::Range(0.0, std::numeric_limits<double>::infinity()));
  app.add_option("--twilight-floor", settings.tracer.twilight_air_floor,
                 "least air majorant of a path's flights at twilight, 1/m (0 = off)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--guide-cell", settings.tracer.guide_cell_m, "cell size of the sun-depth gate, m")
      ->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);
  int w = 0, h = 0;
  const auto set = bench::parse_scene_set(scenes_text);
  if (!bench::parse_frame_size(size, w, h) || !set) {
    std::fprintf(stderr, "truth_scene_probe: --size expects WxH, --scenes core or random:SEED:N\n");
    return 2;
  }
  const std::vector<bench::BenchScene> scenes = bench::make_scene_set(*set, w, h);
  if (index >= static_cast<int>(scenes.size())) {
    std::fprintf(stderr, "truth_scene_probe: --scene %d: the set has %zu scenes\n", index, scenes.size());
    return 2;
  }
  const bench::BenchScene& s = scenes[static_cast<std::size_t>(index)];
  const auto t0 = std::chrono::steady_clock::now();
  const truth::TruthImage t = truth::render_truth(s.view, s.weather, settings);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const FrameImage& img = t.image;
  truth_command::Mask complete(t.incomplete.size());
  for (std::size_t i = 0; i < complete.size(); ++i) complete[i] = t.incomplete[i] ? 0 : 1;
  const double noise = truth_command::truth_noise(img, complete).cloud_rel_se;  // as cloudbench --truth
  const truth::TracerCounters& k = t.counters;
  const double paths = static_cast<double>(std::max<std::uint64_t>(1, k.camera_paths));
  std::printf("%s: %.1f s, %.0f evals/px, per camera path: %.0f collisions, %.1f scatterings, %.2f copies; "
              "lost %llu of %llu paths, incomplete %d px; cloud px %lld, relative noise %.3f\n",
              s.name.c_str(), seconds, img.stats.density_evals_per_pixel, static_cast<double>(k.path_collisions) / paths,
              static_cast<double>(k.scattering_events) / paths, static_cast<double>(k.copies) / paths,
              static_cast<unsigned long long>(k.lost_paths), static_cast<unsigned long long>(k.camera_paths),
              t.incomplete_pixels, static_cast<long long>(img.stats.cloud_pixels), noise);
  {
    // Where the sun is: the droplets' forward peak about it (~0.5 deg) is the brightest part
    // of a view through thin cloud towards it.
    const reference::ReferenceScene rs = reference::make_reference_scene(s.view, s.weather);
    double nearest = 180.0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        nearest = std::min(nearest, glm::degrees(std::acos(std::clamp(
                                        glm::dot(rs.camera.ray_at(x + 0.5, y + 0.5), rs.sun_local), -1.0, 1.0))));
    std::printf("  sun: elevation %.1f deg, %.1f deg from the nearest pixel centre\n", rs.sun_elevation_deg, nearest);
  }
  std::printf("  sun-depth gate: %zu cells, %.0f evaluations per cell, %.1f %% of the evaluations\n", t.sun_depth_cells,
              static_cast<double>(t.sun_depth_evals) / static_cast<double>(std::max<std::size_t>(1, t.sun_depth_cells)),
              100.0 * static_cast<double>(t.sun_depth_evals) /
                  std::max(1.0, img.stats.density_evals_per_pixel * img.width * img.height));
  // Per kind of contribution: share of the estimate and of its second moment (the variance
  // of a heavy-tailed estimate is its second moment), count and largest value.
  double sum = 0, sum2 = 0;
  for (const truth::ContributionStats& c : k.contributions) {
    sum += c.sum;
    sum2 += c.sum2;
  }
  for (int i = 0; i < static_cast<int>(truth::Contribution::Count); ++i) {
    const truth::ContributionStats& c = k.contributions[i];
    std::printf("  %-34s %5.1f %% of the sum, %5.1f %% of the sum of squares, %10llu non-zero, largest %.3g\n",
                truth::kContributionNames[i], sum > 0 ? 100 * c.sum / sum : 0.0, sum2 > 0 ? 100 * c.sum2 / sum2 : 0.0,
                static_cast<unsigned long long>(c.count), c.max);
  }
  return 0;
}
