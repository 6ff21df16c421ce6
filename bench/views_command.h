// `cloudbench --views`: the presets on views the benchmark scene set does not hold
// (tests/fixtures/unseen_views.h: other places, cameras inside a cumulus layer, looking up
// and down, low suns), against the CPU reference, with the cloud silhouettes measured
// (issue 14: the default preset dilated them on a view from inside a layer). For each view
// and configuration the view is held still for 17 frames, as cloudbench holds its scenes
// (a 1/16-px preset visits every pixel once per 16 frames), and the last frame is compared
// with the reference rendered at the size with n x n stratified rays per pixel (its
// footprint, --ref-samples, cached under OUT/ref/): rgb RMSE and PSNR
// (renderer/reference/image_metrics.h), the cloud-pixel fractions (opacity above
// kCloudPixelOpacity) of both, the pixels cloud in one and clear in the other, and the RMSE
// on the reference's cloud edges (compare_silhouettes: pixels within 2 px of a change
// between cloud and clear). Work: density evaluations per pixel per frame, mean of the
// frames after the first (temporal reuse amortised); time: their median render_ms (at
// this small size mostly fixed per-frame costs: `cloudbench --cost` measures speed).
//
// --frame-dt S advances the time by S per frame (the camera still, the clouds drifting
// with their wind); the reference is then rendered at the last frame's time with the
// first frame's wind anchor, as the GPU renderer's clouds are. --ablate adds the default
// preset with one feature changed at a time (no temporal reuse, no footprint jitter,
// strides 1 and 2, no long steps, uniform steps, shadows per pixel). Writes OUT/views.md and
// OUT/views.csv and prints the table.
//
//   build/bin/cloudbench --views [--size 96x54] [--presets naive,default] [--frames 17]
//                        [--frame-dt 0] [--ref-samples 3] [--view N] [--ablate] [--out bench-out]
#pragma once

#include <CLI/CLI.hpp>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_util.h"
#include "bench/image_cache.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/image_metrics.h"
#include "tests/fixtures/unseen_views.h"
#include "weather/presets.h"

namespace cloudsvc::views_command {

struct Config {
  std::string name;
  RenderQuality q;
};

// The default preset with one feature changed at a time (--ablate).
inline std::vector<Config> ablations() {
  const RenderQuality d = *quality_preset("default");
  auto with = [&](const char* name, auto f) {
    RenderQuality q = d;
    f(q);
    return Config{name, q};
  };
  return {with("default, no temporal reuse", [](RenderQuality& q) { q.temporal_reuse = false; q.temporal_stride = 1; }),
          with("default, no footprint jitter", [](RenderQuality& q) { q.footprint_jitter = false; }),
          with("default, 1/1 px (accumulate)", [](RenderQuality& q) { q.temporal_stride = 1; }),
          with("default, 1/4 px", [](RenderQuality& q) { q.temporal_stride = 2; }),
          with("default, no long steps", [](RenderQuality& q) { q.long_step_factor = 1; }),
          with("default, uniform steps", [](RenderQuality& q) { q.step_growth_ref_m = 0.0; }),
          with("default, shadows per pixel", [](RenderQuality& q) { q.ground_shadow_map = false; })};
}

struct Row {
  std::string view, config;
  reference::ImageDifference d;
  reference::SilhouetteDifference s;
  double evals_px = 0.0, median_ms = 0.0;
};

inline std::string file_slug(const std::string& s) {
  std::string o;
  for (char ch : s) o += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return o;
}

// "_strandsR" for each layer whose type draws strands (weather/noise_shaping.h) and
// "_reliefR" for each whose base is textured (CloudTypeTraits::base_relief), for the
// reference cache's key.
inline std::string shape_traits_suffix(const weather::Weather& w) {
  std::string s;
  for (const weather::CloudLayer& l : w.layers) {
    const weather::CloudTypeTraits& t = weather::cloud_type_traits(l.type);
    if (t.strand_ratio != 1.0) s += "_strands" + std::to_string(t.strand_ratio);
    if (t.base_relief != 0.0) s += "_relief" + std::to_string(t.base_relief);
  }
  return s;
}

inline int run(int argc, char** argv) {
  CLI::App app{"Presets on views beyond the benchmark scenes, against the CPU reference (cloudbench --views)"};
  std::string size = "96x54", presets_text = "naive,default", out = "bench-out";
  int frames = 17, ref_samples = 3, only = -1;
  double frame_dt = 0.0;
  bool ablate = false;
  app.add_option("--size", size, "frame size WxH (error and reference)");
  app.add_option("--presets", presets_text, "comma-separated quality presets; RMSE ratios are to the first");
  app.add_option("--frames", frames, "frames of the still view; the last is measured")->check(CLI::Range(1, 1000));
  app.add_option("--frame-dt", frame_dt, "seconds between frames (the clouds drift with their wind)")
      ->check(CLI::Range(0.0, 0.5));
  app.add_option("--ref-samples", ref_samples, "reference rays per pixel along each axis")->check(CLI::Range(1, 8));
  app.add_option("--view", only, "only the view with this index (0 = issue 14's)");
  app.add_flag("--ablate", ablate, "also the default preset with one feature changed at a time");
  app.add_option("--out", out, "output directory (reference cache in OUT/ref/)");
  CLI11_PARSE(app, argc, argv);
  int w = 0, h = 0;
  if (!bench::parse_frame_size(size, w, h)) {
    std::fprintf(stderr, "cloudbench --views: --size expects WxH\n");
    return 2;
  }
  std::vector<Config> configs;
  std::stringstream ss(presets_text);
  for (std::string name; std::getline(ss, name, ',');) {
    const auto q = quality_preset(name);
    if (!q) {
      std::fprintf(stderr, "cloudbench --views: unknown or CPU-only preset %s\n", name.c_str());
      return 2;
    }
    configs.push_back({name, *q});
  }
  if (configs.empty()) return 2;
  if (ablate)
    for (const Config& c : ablations()) configs.push_back(c);

  const std::filesystem::path dir = out;
  std::filesystem::create_directories(dir);
  gl::EglContext context;
  CloudRenderer renderer;
  std::vector<Row> rows;
  const auto& views = fixtures::unseen_views();
  for (int i = 0; i < static_cast<int>(views.size()); ++i) {
    if (only >= 0 && i != only) continue;
    const fixtures::UnseenView& uv = views[static_cast<size_t>(i)];
    const weather::Weather weather = *weather::preset(uv.preset);
    const ViewRequest first = fixtures::unseen_view(uv, w, h);
    ViewRequest last = first;
    last.unix_time_s += frame_dt * (frames - 1);
    last.frame_index = static_cast<std::uint32_t>(frames - 1);
    const WindAnchor anchor{first.position, first.unix_time_s};
    // the reference of each light model the configurations draw (reference::same_light_model)
    std::map<std::pair<bool, bool>, bench::CachedImage> refs;
    auto reference_of = [&](const RenderQuality& q) -> const bench::CachedImage& {
      reference::ReferenceSettings settings = reference::same_light_model(q);
      settings.pixel_samples = ref_samples;
      const std::pair<bool, bool> model{settings.column_depths, settings.sun_slab_tilt};
      if (const auto it = refs.find(model); it != refs.end()) return it->second;
      char key[320];  // the cache file names everything the reference depends on
      std::snprintf(key, sizeof key, "view_%s_%g_%g_%g_%g_%g_%s_%dx%d_ss%d_dt%gx%d_lm%d%s%s%s", uv.preset, uv.lat_deg,
                    uv.lon_deg, uv.alt_m, uv.heading_deg, uv.pitch_deg, uv.time_utc, w, h, ref_samples, frame_dt, frames,
                    reference::kLightModelRevision, model.first ? "_columns" : "", model.second ? "_tilt" : "",
                    shape_traits_suffix(weather).c_str());
      bench::CachedImage ref = bench::cached_render(dir / "ref" / (file_slug(key) + ".exr"), key, w, h, [&] {
        bench::CachedImage c;
        c.img = reference::render_reference(last, weather, settings, &anchor);
        return c;
      });
      std::printf("%s: reference%s %s %.1f s, cloud %.1f %%\n", uv.name, model.first ? " (column depths)" : "",
                  ref.cached ? "(cached)" : "rendered", ref.seconds, 100.0 * reference::cloud_pixel_fraction(ref.img));
      std::fflush(stdout);
      return refs.emplace(model, std::move(ref)).first->second;
    };
    for (const Config& c : configs) {
      const bench::CachedImage& ref = reference_of(c.q);
      renderer.set_weather(weather);  // a new history and wind anchor: the first frame's
      ViewRequest v = first;
      v.reset_history = true;
      FrameImage img;
      std::vector<double> ms;
      double evals = 0.0;
      for (int f = 0; f < frames; ++f) {
        v.frame_index = static_cast<std::uint32_t>(f);
        v.unix_time_s = first.unix_time_s + frame_dt * f;
        img = renderer.render(v, c.q);
        v.reset_history = false;
        if (f > 0 || frames == 1) {
          ms.push_back(img.stats.render_ms);
          evals += img.stats.density_evals_per_pixel;
        }
      }
      Row r;
      r.view = uv.name;
      r.config = c.name;
      r.d = reference::compare_images(img, ref.img);
      r.s = reference::compare_silhouettes(img, ref.img);
      r.evals_px = evals / static_cast<double>(ms.size());
      r.median_ms = bench::median(ms);
      rows.push_back(r);
      if (img.stats.nonfinite_pixels) std::fprintf(stderr, "cloudbench --views: %s: non-finite pixels\n", c.name.c_str());
    }
  }

  std::ostringstream md;
  md << "| view | config | PSNR dB | RMSE | RMSE / " << configs[0].name
     << " | cloud px % (reference) | false cloud px % | missed cloud px % | edge RMSE | edge RMSE / " << configs[0].name
     << " | evals/px | median ms |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  std::ofstream csv(dir / "views.csv");
  csv << "view,config,psnr_db,rmse,cloud_fraction,reference_cloud_fraction,false_cloud,missed_cloud,edge_rmse,"
         "edge_pixels,density_evals_per_px,median_ms\n";
  const Row* base = nullptr;
  for (const Row& r : rows) {
    if (r.config == configs[0].name) base = &r;
    char line[512];
    std::snprintf(line, sizeof line,
                  "| %s | %s | %.2f | %.3e | %.2f | %.1f (%.1f) | %.1f | %.1f | %.3e | %.2f | %.1f | %.1f |\n",
                  r.view.c_str(), r.config.c_str(), r.d.psnr_db, r.d.rmse, base ? r.d.rmse / base->d.rmse : 0.0,
                  100.0 * r.s.test_cloud, 100.0 * r.s.reference_cloud, 100.0 * r.s.false_cloud, 100.0 * r.s.missed_cloud,
                  r.s.edge_rmse, base && base->s.edge_rmse > 0 ? r.s.edge_rmse / base->s.edge_rmse : 0.0, r.evals_px,
                  r.median_ms);
    md << line;
    csv << '"' << r.view << "\",\"" << r.config << "\"," << r.d.psnr_db << ',' << r.d.rmse << ',' << r.s.test_cloud << ','
        << r.s.reference_cloud << ',' << r.s.false_cloud << ',' << r.s.missed_cloud << ',' << r.s.edge_rmse << ','
        << r.s.edge_pixels << ',' << r.evals_px << ',' << r.median_ms << '\n';
  }
  std::ofstream(dir / "views.md") << md.str();
  std::printf("\n%s", md.str().c_str());
  return 0;
}

}  // namespace cloudsvc::views_command
