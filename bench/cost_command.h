// `cloudbench --cost`: the cost half of the run-time-vs-error benchmark, without the CPU
// reference: for each of the eight benchmark scenes (tests/fixtures/accuracy_scenes.h) and each
// quality preset named, the view held still, a first full frame, then N timed frames
// (temporal reuse amortised, as in cloudbench's cost column); median render_ms and the
// median GPU time of each pass. Prints a Markdown table and the sum-of-medians ratio of
// each preset to the first one; the same for the fastest frame of each (sums of minima:
// the least disturbed by other load). Also the density evaluations per pixel per frame (the
// march's work, independent of the machine: primary, light-march and shadow-map samples)
// and their ratio. Also the process CPU time per frame (all llvmpipe threads;
// CLOCK_PROCESS_CPUTIME_ID), which other load on the machine inflates far less than the
// wall clock: the column to compare while anything else runs. For iterating on speed;
// accuracy is cloudbench's.
//
//   build/bin/cloudbench --cost [--size 160x90] [--frames 16] [--presets naive,default] [--cumulus-domes on|off]
//                               [--column-steps 0,3]
// --column-steps measures each preset once per value given (RenderQuality::column_steps),
// labelled "PRESET c=N", interleaved scene by scene.
#pragma once

#include <CLI/CLI.hpp>

#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/quality_presets.h"
#include "tests/fixtures/accuracy_scenes.h"
#include "weather/presets.h"

namespace cloudsvc::cost_command {

inline double process_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

inline int run(int argc, char** argv) {
  CLI::App app{"Cost of quality presets on the benchmark scenes, no reference (cloudbench --cost)"};
  std::string size = "160x90", presets_text = "naive,default";
  std::vector<int> column_steps;
  int frames = 16;
  RendererConfig config;
  app.add_option("--size", size, "frame size WxH");
  app.add_option("--cumulus-domes", config.cumulus_domes, "draw cumulus layers as individual domes (RendererConfig::cumulus_domes)");
  app.add_option("--noise-tiling", config.noise_tiling, "read the noise through its stochastic tiling (RendererConfig::noise_tiling)");
  app.add_option("--frames", frames, "timed frames after the first (median)")->check(CLI::Range(1, 1000));
  app.add_option("--presets", presets_text, "comma-separated quality presets; ratios are to the first");
  app.add_option("--column-steps", column_steps,
                 "comma-separated RenderQuality::column_steps; each preset is measured at each; -N: N steps "
                 "marched from each lit sample instead of the column volume (RenderQuality::column_volume off)")
      ->delimiter(',')
      ->check(CLI::Range(-64, 64));
  CLI11_PARSE(app, argc, argv);
  int w = 0, h = 0;
  if (!bench::parse_frame_size(size, w, h)) {
    std::fprintf(stderr, "cloudbench --cost: --size expects WxH\n");
    return 2;
  }
  std::vector<std::pair<std::string, RenderQuality>> presets;
  std::stringstream ss(presets_text);
  for (std::string name; std::getline(ss, name, ',');) {
    const auto q = quality_preset(name);
    if (!q || name == "reference") {
      std::fprintf(stderr, "cloudbench --cost: unknown or CPU-only preset %s\n", name.c_str());
      return 2;
    }
    if (column_steps.empty()) presets.push_back({name, *q});
    for (const int n : column_steps) {
      RenderQuality v = *q;
      v.column_steps = std::abs(n);
      v.column_volume = n >= 0;
      presets.push_back({name + (n >= 0 ? " c=" : " marched c=") + std::to_string(std::abs(n)), v});
    }
  }
  if (presets.empty()) return 2;

  gl::EglContext context;
  CloudRenderer renderer(config);
  std::vector<double> sums(presets.size(), 0.0), cpu_sums(presets.size(), 0.0), min_sums(presets.size(), 0.0),
      eval_sums(presets.size(), 0.0);
  std::printf("| scene | preset | median ms | CPU ms/frame | march | resolve | composite | LUTs | shadow map | read-back | density evals/px |\n"
              "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const accuracy::AccuracyScene& s : accuracy::accuracy_scenes()) {
    if (!s.core) continue;
    renderer.set_weather(*weather::preset(s.preset));
    ViewRequest v = accuracy::accuracy_view(s, w, h);
    renderer.render(v);  // shader JIT and weather upload outside the timed frames
    for (size_t p = 0; p < presets.size(); ++p) {
      v.reset_history = true;
      v.frame_index = 0;
      renderer.render(v, presets[p].second);
      v.reset_history = false;
      std::vector<double> ms, march, resolve, composite, luts, shadow, readback;
      double evals = 0.0;  // density evaluations per pixel, summed over the timed frames
      const double cpu0 = process_cpu_ms();
      for (int f = 1; f <= frames; ++f) {
        v.frame_index = static_cast<std::uint32_t>(f);
        const FrameStats st = renderer.render(v, presets[p].second).stats;
        ms.push_back(st.render_ms);
        march.push_back(st.march_ms);
        resolve.push_back(st.resolve_ms);
        composite.push_back(st.composite_ms);
        luts.push_back(st.luts_ms);
        shadow.push_back(st.shadow_map_ms);
        readback.push_back(st.readback_ms);
        evals += st.density_evals_per_pixel;
      }
      const double cpu_ms = (process_cpu_ms() - cpu0) / frames;
      sums[p] += bench::median(ms);
      min_sums[p] += *std::min_element(ms.begin(), ms.end());
      cpu_sums[p] += cpu_ms;
      eval_sums[p] += evals / frames;
      std::printf("| %s | %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", s.name, presets[p].first.c_str(),
                  bench::median(ms), cpu_ms, bench::median(march), bench::median(resolve), bench::median(composite), bench::median(luts),
                  bench::median(shadow), bench::median(readback), evals / frames);
      std::fflush(stdout);
    }
  }
  const char* first = presets[0].first.c_str();
  std::printf("\n| preset | sum of medians ms | %s / preset | sum of minima ms | %s / preset | sum CPU ms/frame | %s / preset "
              "| density evals/px (sum) | %s / preset |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
              first, first, first, first);
  for (size_t p = 0; p < presets.size(); ++p)
    std::printf("| %s | %.1f | %.2f | %.1f | %.2f | %.1f | %.2f | %.1f | %.1f |\n", presets[p].first.c_str(), sums[p],
                sums[0] / sums[p], min_sums[p], min_sums[0] / min_sums[p], cpu_sums[p], cpu_sums[0] / cpu_sums[p],
                eval_sums[p], eval_sums[0] / std::max(eval_sums[p], 1e-9));
  return 0;
}

}  // namespace cloudsvc::cost_command
