// `cloudbench --truth`: the presets, the naive march and the CPU model reference against the
// path-traced ground truth (docs/TRUTH.md), side by side with their error against the model
// reference, on a scene set (core or random:SEED:N, bench_scenes.h).
//
// Per scene: the truth (spp paths per pixel, with its standard error) and the reference
// (ref-samples^2 rays per pixel: the pixel footprint), both cached under OUT/truth and
// OUT/ref (bench/image_cache.h); every quality preset rendered as cloudbench does (the
// view held still for 17 frames, so temporal presets have converged; the error of the
// last frame) with its density evaluations per pixel per frame over those frames (the
// march's work, independent of the machine). Errors on linear radiance:
//   - against the truth, corrected for the truth's own noise: MSE_true = MSE - mean(se^2)
//     (the truth's error is independent of the test image's, so E[MSE] adds its variance);
//     RMSE = sqrt(max(0, MSE_true)); PSNR with the truth's largest rgb as the peak; the mean
//     relative error over the truth's cloud pixels (opacity > 0.01), |x - t| / t per
//     channel, with the truth's own mean relative standard error there as its noise floor;
//   - against the reference: the same without the correction (bench/scene_statistics.h).
// Aggregated over scenes: mean and 90th percentile (PSNR: 10th) of each per-scene error.
//
// Deep inside optically thick clouds a path scatters 1e4-1e6 times (the count grows with the
// square of the optical depth); a pixel one of whose paths exceeds --max-collisions
// tentative collisions stops there and is left out of every metric (its share is reported).
//
//   build/bin/cloudbench --truth [--scenes core|random:SEED:N (random:2026:32)] [--size WxH (24x14)]
//                        [--spp N (32)] [--ref-samples N (3)] [--max-collisions N (50000)]
//                        [--out DIR (bench-out-truth)]
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_scenes.h"
#include "bench/bench_util.h"
#include "bench/image_cache.h"
#include "bench/scene_statistics.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/image_metrics.h"

namespace cloudsvc::truth_command {

// Errors of one image against the truth (noise-corrected) and the reference.
struct Errors {
  double truth_rmse = 0, truth_psnr = 0, truth_cloud_rel = std::numeric_limits<double>::quiet_NaN();
  double ref_rmse = 0, ref_psnr = 0, ref_cloud_rel = std::numeric_limits<double>::quiet_NaN();
};

struct TruthNoise {
  // sqrt(mean se^2) / mean t over the truth's cloud pixels: the truth's own relative noise
  double cloud_rel_se = std::numeric_limits<double>::quiet_NaN();
};

// Pixels the comparison uses: those whose truth is complete (TruthImage::incomplete).
using Mask = std::vector<std::uint8_t>;

inline TruthNoise truth_noise(const FrameImage& t, const Mask& valid) {
  TruthNoise n;
  double rel = 0, cloud_t = 0;
  long rel_n = 0;
  const size_t pixels = static_cast<size_t>(t.width) * t.height;
  for (size_t i = 0; i < pixels; ++i) {
    if (!valid[i] || !(t.rgba[i * 4 + 3] > bench::kCloudOpacity)) continue;
    for (int c = 0; c < 3; ++c) {
      const double se = t.std_error[i * 3 + c];
      rel += se * se;
      cloud_t += t.rgba[i * 4 + c];
      ++rel_n;
    }
  }
  if (rel_n && cloud_t > 0) n.cloud_rel_se = std::sqrt(rel / rel_n) / (cloud_t / rel_n);
  return n;
}

// RMSE, PSNR (peak: the largest rgb of `ref`) and the relative RMSE over ref's cloud pixels
// (RMSE there / mean radiance there: a ratio of aggregates, which a pixel whose truth is
// near 0 cannot blow up) of img against ref, over the valid pixels; the noise variance
// `se` (per pixel and channel; empty = none) is subtracted from the squared errors.
inline void compare(const FrameImage& img, const FrameImage& ref, const Mask& valid, const std::vector<float>& se,
                    double& rmse, double& psnr, double& cloud_rel) {
  double mse = 0, peak = 0, cloud_se2 = 0, cloud_mean = 0;
  long n = 0, cloud_n = 0;
  const size_t pixels = static_cast<size_t>(img.width) * img.height;
  for (size_t i = 0; i < pixels; ++i) {
    if (!valid[i]) continue;
    ++n;
    const bool cloud = ref.rgba[i * 4 + 3] > bench::kCloudOpacity;
    for (int c = 0; c < 3; ++c) {
      const double r = ref.rgba[i * 4 + c], d = static_cast<double>(img.rgba[i * 4 + c]) - r;
      const double noise = se.empty() ? 0.0 : static_cast<double>(se[i * 3 + c]) * se[i * 3 + c];
      mse += d * d - noise;
      peak = std::max(peak, r);
      if (cloud) {
        cloud_se2 += d * d - noise;
        cloud_mean += r;
        ++cloud_n;
      }
    }
  }
  rmse = std::sqrt(std::max(0.0, mse / static_cast<double>(std::max(1L, n * 3))));
  psnr = rmse > 0 ? 20.0 * std::log10(peak / rmse) : std::numeric_limits<double>::infinity();
  cloud_rel = cloud_n && cloud_mean > 0
                  ? std::sqrt(std::max(0.0, cloud_se2 / cloud_n)) / (cloud_mean / static_cast<double>(cloud_n))
                  : std::numeric_limits<double>::quiet_NaN();
}

inline Errors errors_of(const FrameImage& img, const FrameImage& truth, const FrameImage& ref, const Mask& valid) {
  Errors e;
  compare(img, truth, valid, truth.std_error, e.truth_rmse, e.truth_psnr, e.truth_cloud_rel);
  compare(img, ref, valid, {}, e.ref_rmse, e.ref_psnr, e.ref_cloud_rel);
  return e;
}

struct Row {
  std::string scene, config;
  double evals_px = 0;  // per frame, mean over the 17 frames (reference: its own count)
  Errors e;
};

// The scene's parameters in one line.
inline std::string describe(const bench::BenchScene& s) {
  const ViewRequest& v = s.view;
  char b[256];
  std::snprintf(b, sizeof b, "%s: lat %.4f lon %.4f alt %.0f m%s, hdg %.1f pitch %.1f roll %.1f, fov %.1f, %s, sun el %.1f; ",
                s.name.c_str(), v.position.lat_deg, v.position.lon_deg, v.position.alt_m,
                s.inside_layer ? " (inside a layer)" : "", v.attitude.heading_deg, v.attitude.pitch_deg,
                v.attitude.roll_deg, v.fov_deg, geo::format_utc_iso8601(v.unix_time_s).c_str(), s.sun_elevation_deg);
  return b + s.weather_label;
}

// A scene's truth resolves cloud radiance when its relative noise there is at most this
// (and the sun is above the horizon).
inline constexpr double kResolvedNoise = 0.25;

// Pixels the comparison can use: not incomplete in the truth.
inline Mask complete_pixels(const bench::CachedImage& truth) {
  Mask valid(static_cast<size_t>(truth.img.width) * truth.img.height, 1);
  for (size_t i = 0; i < valid.size() && i < truth.incomplete.size(); ++i)
    if (truth.incomplete[i]) valid[i] = 0;
  return valid;
}

// Adds batch b (another seed, the same spp) to the running truth `sum` of `batches` batches:
// independent estimates of equal size, so the mean is the mean of the means, the standard
// error sqrt(sum se_k^2) / K, the opacity the mean opacity; a pixel incomplete in any batch
// is incomplete.
inline void add_batch(bench::CachedImage& sum, const bench::CachedImage& b, int batches) {
  const double k = static_cast<double>(batches);  // batches in sum before b
  for (size_t i = 0; i < sum.img.rgba.size(); ++i)
    sum.img.rgba[i] = static_cast<float>((sum.img.rgba[i] * k + b.img.rgba[i]) / (k + 1.0));
  for (size_t i = 0; i < sum.img.std_error.size(); ++i) {
    const double a = sum.img.std_error[i] * k, c = b.img.std_error[i];
    sum.img.std_error[i] = static_cast<float>(std::sqrt(a * a + c * c) / (k + 1.0));
  }
  for (size_t i = 0; i < sum.incomplete.size() && i < b.incomplete.size(); ++i) sum.incomplete[i] |= b.incomplete[i];
  sum.seconds += b.seconds;
  sum.evals_px += b.evals_px;
  sum.cached = sum.cached && b.cached;
}

// The scene's truth: a first batch of spp paths per pixel (seed 1), and when its cloud
// radiance is too noisy to resolve (relative noise > kResolvedNoise) as many batches in all
// (seeds 2, 3, ...) as that noise says are needed to reach 0.8 kResolvedNoise (noise falls
// as 1/sqrt(paths)) if that is at most max_spp paths per pixel (else one batch: the time
// would not resolve it). The count is fixed by the first batch, not by testing after each
// batch, which would favour stopping on batches whose heavy tail happened to be missing. A
// scene without cloud pixels gets one batch.
inline bench::CachedImage adaptive_truth(const bench::BenchScene& s, const std::filesystem::path& dir, int w, int h,
                                         int spp, int max_spp, std::uint64_t max_collisions, int& spp_used) {
  bench::CachedImage t = bench::truth_image(s, dir, w, h, spp, max_collisions, 1);
  const double noise = truth_noise(t.img, complete_pixels(t)).cloud_rel_se;
  int batches = 1;
  if (noise > kResolvedNoise) {
    const double ratio = noise / (0.8 * kResolvedNoise);
    const int needed = static_cast<int>(std::min(1e6, std::ceil(ratio * ratio)));
    if (needed <= max_spp / spp) batches = needed;  // else max_spp cannot resolve it: one batch
  }
  for (int b = 1; b < batches; ++b)
    add_batch(t, bench::truth_image(s, dir, w, h, spp, max_collisions, static_cast<std::uint64_t>(b) + 1), b);
  spp_used = batches * spp;
  return t;
}

// Whether some row is of config `name`.
inline bool has_config(const std::vector<Row>& rows, const std::string& name) {
  return std::any_of(rows.begin(), rows.end(), [&](const Row& r) { return r.config == name; });
}

inline std::string num(const char* f, double v) {
  if (!std::isfinite(v)) return "-";
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

inline int run(int argc, char** argv) {
  CLI::App app{"Presets and the model reference against the path-traced ground truth (cloudbench --truth)"};
  std::string scenes_text = "random:2026:32", size = "24x14", out = "bench-out-truth";
  int spp = 32, max_spp = 0, ref_samples = 3;
  std::uint64_t max_collisions = 50000;
  int column_steps = -1;
  app.add_option("--scenes", scenes_text, "core or random:SEED:N");
  app.add_option("--column-steps", column_steps,
                 "RenderQuality::column_steps of every preset (the diffuse light's depths from each point's own "
                 "column if > 0); default: each preset's own. Each preset is compared with the reference of its "
                 "own light model (reference::same_light_model)")
      ->check(CLI::Range(0, 64));
  bool sun_slab_tilt = false;
  app.add_flag("--sun-slab-tilt", sun_slab_tilt,
               "every preset and the reference read the sun's diffuse source from the slab tilted towards the sun "
               "(RenderQuality::sun_slab_tilt, ReferenceSettings::sun_slab_tilt) where they draw column depths");
  bool column_march = false;
  app.add_flag("--column-march", column_march,
               "with --column-steps: every preset marches the column depths from each lit sample instead of "
               "reading the column volume (RenderQuality::column_volume off)");
  app.add_option("--size", size, "image size WxH of every render");
  app.add_option("--spp", spp, "paths per pixel of the truth (one batch)")->check(CLI::Range(2, 1 << 20));
  app.add_option("--max-spp", max_spp,
                 "more batches of --spp paths (other seeds) while a scene's truth is too noisy to resolve its "
                 "cloud radiance, up to this many paths per pixel; default --spp (one batch)")
      ->check(CLI::Range(2, 1 << 24));
  app.add_option("--ref-samples", ref_samples, "reference rays per pixel along each axis")->check(CLI::Range(1, 16));
  app.add_option("--out", out, "output directory (report.md, report.csv, cached images)");
  app.add_option("--max-collisions", max_collisions,
                 "tentative collisions per truth path beyond which its pixel is left out (incomplete)")
      ->check(CLI::Range(static_cast<std::uint64_t>(1000), static_cast<std::uint64_t>(1) << 40));
  CLI11_PARSE(app, argc, argv);
  // a preset as this run draws it
  auto quality_of = [&](const std::string& name) {
    RenderQuality q = *quality_preset(name);
    if (column_steps >= 0) q.column_steps = column_steps;
    if (column_march) q.column_volume = false;
    if (sun_slab_tilt) q.sun_slab_tilt = true;
    return q;
  };
  // the reference row of a light model: "reference" draws the homogeneous layer's depths
  auto reference_name = [](bool columns) { return std::string(columns ? "reference, columns" : "reference"); };
  max_spp = std::max(max_spp, spp);
  int w = 0, h = 0;
  if (!bench::parse_frame_size(size, w, h)) {
    std::fprintf(stderr, "cloudbench --truth: --size expects WxH\n");
    return 2;
  }
  if (sun_slab_tilt && column_steps == 0) {
    std::fprintf(stderr, "cloudbench --truth: --sun-slab-tilt needs column depths (not --column-steps 0: the tilt compares "
                         "the sun's depth with each point's own column)\n");
    return 2;
  }
  const auto set = bench::parse_scene_set(scenes_text);
  if (!set) {
    std::fprintf(stderr, "cloudbench --truth: --scenes expects core or random:SEED:N (N in 1..%d)\n",
                 bench::kMaxRandomScenes);
    return 2;
  }
  const std::filesystem::path dir = out;
  std::filesystem::create_directories(dir);
  const auto t_start = std::chrono::steady_clock::now();
  gl::EglContext context;
  CloudRenderer renderer;
  const std::vector<bench::BenchScene> scenes = bench::make_scene_set(*set, w, h);
  std::vector<std::string> configs = quality_preset_names();  // naive first
  std::vector<Row> rows;
  std::vector<TruthNoise> noises;
  std::vector<double> incomplete_share;
  std::vector<int> truth_spp;  // paths per pixel each scene's truth used
  double truth_s = 0, ref_s = 0;
  for (const bench::BenchScene& s : scenes) {
    int scene_spp = 0;
    const bench::CachedImage truth = adaptive_truth(s, dir / "truth", w, h, spp, max_spp, max_collisions, scene_spp);
    // the reference of each light model the presets draw (at most two: with and without columns)
    std::map<bool, bench::CachedImage> refs;
    double scene_ref_s = 0;
    for (const std::string& name : configs) {
      const reference::ReferenceSettings m = reference::same_light_model(quality_of(name));
      if (refs.count(m.column_depths)) continue;
      refs[m.column_depths] =
          bench::reference_image(s, dir / "ref", w, h, ref_samples, m.column_depths, m.sun_slab_tilt);
      scene_ref_s += refs[m.column_depths].seconds;
    }
    ref_s += scene_ref_s;
    truth_s += truth.seconds;
    truth_spp.push_back(scene_spp);
    const Mask valid = complete_pixels(truth);
    const int incomplete = static_cast<int>(std::count(valid.begin(), valid.end(), 0));
    incomplete_share.push_back(static_cast<double>(incomplete) / static_cast<double>(valid.size()));
    const TruthNoise noise = truth_noise(truth.img, valid);
    noises.push_back(noise);
    std::printf("%-12s truth %s %.1f s (%d spp, %.0f evals/px, %d incomplete px), references %.1f s; %s\n",
                s.name.c_str(), truth.cached ? "cached" : "rendered", truth.seconds, scene_spp, truth.evals_px, incomplete,
                scene_ref_s, describe(s).c_str());
    std::fflush(stdout);
    for (const auto& [columns, ref] : refs)
      rows.push_back({s.name, reference_name(columns), ref.evals_px, errors_of(ref.img, truth.img, ref.img, valid)});
    renderer.set_weather(s.weather);
    for (const std::string& name : configs) {
      const RenderQuality q = quality_of(name);
      const bench::CachedImage& ref = refs.at(reference::same_light_model(q).column_depths);
      ViewRequest v = s.view;
      v.reset_history = true;
      FrameImage last;
      double evals = 0;
      constexpr int kStillFrames = 17;  // as cloudbench: temporal presets converge over a 16-frame cycle
      for (int f = 0; f < kStillFrames; ++f) {
        v.frame_index = static_cast<std::uint32_t>(f);
        last = renderer.render(v, q);
        evals += last.stats.density_evals_per_pixel;
        v.reset_history = false;
      }
      rows.push_back({s.name, name, evals / kStillFrames, errors_of(last, truth.img, ref.img, valid)});
    }
  }
  for (const bool columns : {false, true})
    if (has_config(rows, reference_name(columns))) configs.push_back(reference_name(columns));
  const double total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();

  std::ofstream csv(dir / "report.csv");
  csv << "scene,config,density_evals_per_px,truth_rmse,truth_psnr_db,truth_cloud_relative_error,ref_rmse,ref_psnr_db,"
         "ref_cloud_relative_error\n";
  for (const Row& r : rows)
    csv << '"' << r.scene << "\"," << r.config << ',' << r.evals_px << ',' << r.e.truth_rmse << ',' << r.e.truth_psnr << ','
        << (std::isfinite(r.e.truth_cloud_rel) ? std::to_string(r.e.truth_cloud_rel) : "") << ',' << r.e.ref_rmse << ','
        << r.e.ref_psnr << ',' << (std::isfinite(r.e.ref_cloud_rel) ? std::to_string(r.e.ref_cloud_rel) : "") << '\n';

  std::map<std::string, std::vector<const Row*>> by_config;
  for (const Row& r : rows) by_config[r.config].push_back(&r);
  std::vector<double> floor_rel;
  std::map<std::string, bool> resolved;  // scenes whose truth resolves cloud radiance (noise <= kResolvedNoise)
  int resolved_count = 0;
  for (size_t i = 0; i < scenes.size(); ++i) {
    floor_rel.push_back(noises[i].cloud_rel_se);
    resolved[scenes[i].name] = noises[i].cloud_rel_se <= kResolvedNoise;
    resolved_count += resolved[scenes[i].name] ? 1 : 0;
  }
  std::ostringstream md;
  md << "# cloudbench --truth report\n\nCommand: `cloudbench --truth --scenes " << scenes_text << " --size " << size
     << " --spp " << spp << " --max-spp " << max_spp << " --ref-samples " << ref_samples << " --max-collisions "
     << max_collisions << (column_steps >= 0 ? " --column-steps " + std::to_string(column_steps) : std::string())
     << (column_march ? " --column-march" : "") << (sun_slab_tilt ? " --sun-slab-tilt" : "") << "`  \n"
     << scenes.size() << " scenes at " << w << "x" << h << "; truth " << spp << " paths per pixel, more (up to "
     << max_spp << ") where a scene's first batch is too noisy (per scene below) ("
     << num("%.0f", truth_s) << " s of renders, 0 = cached), reference " << ref_samples << "x" << ref_samples
     << " rays per pixel (" << num("%.0f", ref_s) << " s), total " << num("%.0f", total_s) << " s.\n\n"
     << "Cloud relative error = RMSE over the cloud pixels (opacity > 0.01 in the image compared against) and rgb "
        "channels / their mean radiance; against the truth the truth's own variance (se^2) is subtracted from the "
        "squared errors. The truth's own relative noise on cloud pixels (sqrt(mean se^2) / mean radiance): mean "
     << num("%.4f", bench::finite_mean(floor_rel)) << ", p90 " << num("%.4f", bench::percentile(floor_rel, 90))
     << " over the scenes with cloud. Truth columns aggregate the " << resolved_count << " scenes where it is at most "
     << num("%.2f", kResolvedNoise)
     << " (the others: no cloud, or a truth too noisy at this spp). Pixels whose truth is incomplete (a path exceeded "
     << max_collisions << " tentative collisions: deep inside optically thick cloud) are left out of every metric: "
     << num("%.1f", 100.0 * bench::finite_mean(incomplete_share)) << " % of the pixels on average, "
     << num("%.1f", 100.0 * bench::percentile(incomplete_share, 90)) << " % at the 90th percentile of the scenes.\n\n"
     << "| config | evals/px | vs truth: cloud rel. err mean | p90 | PSNR mean dB | p10 | vs reference: cloud rel. err mean "
        "| p90 | PSNR mean dB | p10 |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const std::string& c : configs) {
    std::vector<double> ev, tr, tp, rr, rp;
    for (const Row* r : by_config[c]) {
      ev.push_back(r->evals_px);
      if (resolved[r->scene]) {
        tr.push_back(r->e.truth_cloud_rel);
        tp.push_back(r->e.truth_psnr);
      }
      if (c.rfind("reference", 0) != 0) {
        rr.push_back(r->e.ref_cloud_rel);
        rp.push_back(r->e.ref_psnr);
      }
    }
    md << "| " << c << " | " << num("%.1f", bench::finite_mean(ev)) << " | " << num("%.3f", bench::finite_mean(tr)) << " | "
       << num("%.3f", bench::percentile(tr, 90)) << " | " << num("%.2f", bench::finite_mean(tp)) << " | "
       << num("%.2f", bench::percentile(tp, 10)) << " | " << num("%.3f", bench::finite_mean(rr)) << " | "
       << num("%.3f", bench::percentile(rr, 90)) << " | " << num("%.2f", bench::finite_mean(rp)) << " | "
       << num("%.2f", bench::percentile(rp, 10)) << " |\n";
  }
  // the per-scene table compares the default with the reference of its own model
  const std::string default_ref = reference_name(reference::same_light_model(quality_of("default")).column_depths);
  md << "\n## Per scene (cloud relative error)\n\n| scene | truth spp | incomplete px | truth noise | naive vs truth | default vs truth | "
     << default_ref << " vs truth | default vs reference | naive vs reference |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (size_t i = 0; i < scenes.size(); ++i) {
    auto find = [&](const std::string& c) -> const Row* {
      for (const Row* r : by_config[c])
        if (r->scene == scenes[i].name) return r;
      return nullptr;
    };
    const Row *n = find("naive"), *d = find("default"), *r = find(default_ref);
    md << "| " << scenes[i].name << " | " << truth_spp[i] << " | " << num("%.1f %%", 100.0 * incomplete_share[i]) << " | "
       << num("%.3f", noises[i].cloud_rel_se) << " | "
       << num("%.3f", n->e.truth_cloud_rel) << " | " << num("%.3f", d->e.truth_cloud_rel) << " | "
       << num("%.3f", r->e.truth_cloud_rel) << " | " << num("%.3f", d->e.ref_cloud_rel) << " | "
       << num("%.3f", n->e.ref_cloud_rel) << " |\n";
  }
  md << "\n## Scenes\n\n";
  for (const bench::BenchScene& s : scenes) md << "- " << describe(s) << "\n";
  std::ofstream(dir / "report.md") << md.str();
  std::printf("cloudbench --truth: %zu scenes in %.0f s -> %s\n", scenes.size(), total_s, dir.string().c_str());
  return 0;
}

}  // namespace cloudsvc::truth_command
