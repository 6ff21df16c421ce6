// `cloudbench --stability` (also built as `cloudbench_stability`): the numerical-stability
// stress sweep of issue "Accuracy" part 4 (docs/STABILITY.md).
// Renders --poses tiny frames over the globe (all presets), checks every pixel, then
// --smooth poses for 1 cm / 0.001 deg smoothness, then the 30-day uptime check.
// Prints a Markdown summary on stdout, ending with one "SUMMARY stability ..." line to paste
// (with the commit, `git describe --dirty`); exit status 1 if any check failed.
//
//   build/bin/cloudbench --stability [--poses 10000] [--smooth 200] [--size 32x18] [--seed 1]
//                        [--quality default] [--frames-per-image 8] [--centre | --footprint-jitter] [--long-step N]
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "geodesy/utc_time.h"
#include "renderer/gl/egl_context.h"
#include "renderer/quality_presets.h"
#include "tests/fixtures/stability_sweep.h"
#include "weather/presets.h"

namespace cloudsvc::stability_command {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The whole sweep; argv as for a program (argv[0] is a name). Returns the exit status.
inline int run(int argc, char** argv) {
  CLI::App app{"Numerical-stability stress sweep of the GPU renderer (cloudbench --stability)"};
  int poses = 10000, smooth = 200, max_listed = 20;
  std::uint64_t seed = 1;
  std::string size = "32x18";
  app.add_option("--poses", poses, "frames of the globe sweep (split over all presets)")->check(CLI::Range(1, 10000000));
  app.add_option("--smooth", smooth, "poses of the smoothness check (8 renders each)")->check(CLI::Range(0, 100000));
  app.add_option("--size", size, "frame size WxH");
  app.add_option("--seed", seed, "pose generator seed");
  app.add_option("--list", max_listed, "failures listed in full");
  std::string quality_name = "default";
  app.add_option("--quality", quality_name, "quality preset of the renders (temporal reuse off: single frames)");
  bool footprint_jitter = false;
  app.add_flag("--footprint-jitter", footprint_jitter, "march rays through a different point of the pixel each frame (RenderQuality::footprint_jitter; the temporal presets do)");
  bool centre = false;
  app.add_flag("--centre", centre, "march rays through the pixel centre (footprint jitter off whatever the preset)");
  int frames_per_image = 8;
  app.add_option("--frames-per-image", frames_per_image,
                 "smoothness: each compared image is the mean of this many single frames (stab::SmoothLimits)")
      ->check(CLI::Range(1, 256));
  int long_step = 0;
  app.add_option("--long-step", long_step, "override the preset's long_step_factor (1 = no probing in empty air)")->check(CLI::Range(1, 64));
  CLI11_PARSE(app, argc, argv);
  std::optional<RenderQuality> quality = quality_preset(quality_name);
  if (!quality) {
    std::fprintf(stderr, "cloudbench --stability: unknown --quality %s\n", quality_name.c_str());
    return 2;
  }
  quality->temporal_reuse = false;
  if (footprint_jitter) quality->footprint_jitter = true;
  if (centre) quality->footprint_jitter = false;
  if (long_step > 0) quality->long_step_factor = long_step;
  int w = 0, h = 0;
  if (!bench::parse_frame_size(size, w, h)) {
    std::fprintf(stderr, "--size: expected WxH, got %s\n", size.c_str());
    return 2;
  }

  const auto t_start = Clock::now();
  gl::EglContext context;
  CloudRenderer renderer;
  const std::vector<std::string> presets = weather::preset_names();
  bool all_ok = true;

  // ---- 1. globe sweep
  std::int64_t frames = 0, failed = 0, bad_values = 0, nonfinite = 0, gl_errors = 0, exceptions = 0;
  double sun_min = 1e9, sun_max = -1e9, ms_sum = 0.0;
  int sun_bins[12] = {};  // sun elevation histogram, 10 deg bins from -30
  std::vector<std::string> failures;
  const auto t1 = Clock::now();
  for (size_t p = 0; p < presets.size(); ++p) {
    const int n = poses / static_cast<int>(presets.size()) + (static_cast<int>(p) < poses % static_cast<int>(presets.size()) ? 1 : 0);
    renderer.set_weather(*weather::preset(presets[p]));
    for (const stab::Pose& pose : stab::make_poses(presets[p], n, seed * 1000 + p, w, h)) {
      const stab::FrameCheck c = stab::check_frame(renderer, pose.view, nullptr, *quality);
      ++frames;
      bad_values += c.bad_values;
      nonfinite += c.nonfinite_stat;
      gl_errors += c.gl_errors;
      exceptions += c.exception.empty() ? 0 : 1;
      ms_sum += c.render_ms;
      sun_min = std::min(sun_min, c.sun_elevation_deg);
      sun_max = std::max(sun_max, c.sun_elevation_deg);
      sun_bins[std::clamp(static_cast<int>(std::floor((c.sun_elevation_deg + 30.0) / 10.0)), 0, 11)]++;
      if (!c.ok()) {
        ++failed;
        char buf[160];
        std::snprintf(buf, sizeof buf, " | bad %lld, nonfinite %lld, loop-capped %lld, gl %d, %s",
                      static_cast<long long>(c.bad_values), static_cast<long long>(c.nonfinite_stat),
                      static_cast<long long>(c.loop_capped), c.gl_errors, c.exception.c_str());
        failures.push_back(stab::describe(pose) + buf);
      }
      if (frames % 500 == 0)
        std::fprintf(stderr, "sweep %lld frames, %lld failed, %.0f s\n", static_cast<long long>(frames),
                     static_cast<long long>(failed), seconds_since(t1));
    }
  }
  const double sweep_s = seconds_since(t1);
  all_ok = all_ok && failed == 0;

  std::printf("# cloudbench_stability (`cloudbench --stability`)\n\n");
  std::printf("Frame size %dx%d, seed %llu, %zu presets, quality %s (single frames).\n\n", w, h,
              static_cast<unsigned long long>(seed), presets.size(), quality_name.c_str());
  std::printf("## 1. Globe sweep\n\n| frames | failed | bad pixel values | stats.nonfinite_pixels | GL errors | exceptions | "
              "sun elevation range | mean ms/frame | wall s |\n|---|---|---|---|---|---|---|---|---|\n");
  std::printf("| %lld | %lld | %lld | %lld | %lld | %lld | %.2f .. %.2f deg | %.1f | %.0f |\n\n", static_cast<long long>(frames),
              static_cast<long long>(failed), static_cast<long long>(bad_values), static_cast<long long>(nonfinite),
              static_cast<long long>(gl_errors), static_cast<long long>(exceptions), sun_min, sun_max,
              ms_sum / std::max<std::int64_t>(frames, 1), sweep_s);
  std::printf("Sun elevation histogram (frames per 10 deg bin from -30 deg):");
  for (int b : sun_bins) std::printf(" %d", b);
  std::printf("\n\n");
  for (size_t i = 0; i < failures.size() && static_cast<int>(i) < max_listed; ++i) std::printf("- FAIL %s\n", failures[i].c_str());

  // ---- 2. smoothness
  const auto t2 = Clock::now();
  int pairs = 0, pair_fail = 0;
  double worst_step = 0.0, worst_frac = 0.0, worst_mean = 0.0, worst_ratio = 0.0, sum_jitter = 0.0;
  std::string worst_pose;
  std::vector<std::string> smooth_fail;
  // Per step kind: the per-pixel statistics (stab::PixelStats; gated against the wide floor).
  const stab::PixelLimits plim;
  stab::SmoothLimits slim;
  slim.frames_per_image = frames_per_image;
  struct Kind {
    std::string what;
    int pairs = 0, gate_fail = 0, pixel_fail = 0, pixels_over = 0, no_noise = 0, wide_fail = 0, wide_over = 0, wide_no_noise = 0;
    double max_ratio = 0.0, max_criterion = 0.0, worst_s = 0.0, worst_j = 0.0;
    std::string worst_pose;
  };
  std::vector<Kind> kinds;
  int pixel_fail_pairs = 0, wide_fail_pairs = 0;
  const std::vector<stab::Pose> sp = stab::make_smooth_poses(presets, smooth, seed * 7 + 3, w, h);
  std::string current;
  for (const stab::Pose& pose : sp) {
    if (pose.preset != current) { renderer.set_weather(*weather::preset(pose.preset)); current = pose.preset; }
    for (const stab::SmoothResult& r : stab::check_smoothness(renderer, pose.view, slim, *quality, plim)) {
      ++pairs;
      {
        auto it = std::find_if(kinds.begin(), kinds.end(), [&](const Kind& k) { return k.what == r.what; });
        if (it == kinds.end()) {
          kinds.emplace_back();
          kinds.back().what = r.what;
          it = kinds.end() - 1;
        }
        Kind& k = *it;
        ++k.pairs;
        k.gate_fail += r.ok ? 0 : 1;
        k.pixel_fail += r.pixels.ok() ? 0 : 1;
        pixel_fail_pairs += r.pixels.ok() ? 0 : 1;
        k.pixels_over += r.pixels.pixels_over;
        k.wide_fail += r.pixels.ok_wide() ? 0 : 1;
        wide_fail_pairs += r.pixels.ok_wide() ? 0 : 1;
        k.wide_over += r.pixels.pixels_over_wide;
        k.wide_no_noise += r.pixels.wide_without_noise;
        k.no_noise += r.pixels.changed_without_noise;
        k.max_ratio = std::max(k.max_ratio, r.pixels.max_ratio);
        if (r.pixels.max_criterion > k.max_criterion) {
          k.max_criterion = r.pixels.max_criterion;
          k.worst_s = r.pixels.worst_s;
          k.worst_j = r.pixels.worst_j;
          char at[64];
          std::snprintf(at, sizeof at, "pixel (%d,%d): ", r.pixels.worst_x, r.pixels.worst_y);
          k.worst_pose = at + stab::describe(pose);
        }
      }
      sum_jitter += r.jitter.mean_rel;
      if (r.step.max_rel > worst_step) { worst_step = r.step.max_rel; worst_pose = r.what + ": " + stab::describe(pose); }
      worst_frac = std::max(worst_frac, r.step.frac_above);
      worst_mean = std::max(worst_mean, r.step.mean_rel);
      if (std::getenv("STAB_VERBOSE")) std::fprintf(stderr, "pair %s max %.3g frac %.4f mean %.3g jitter %.3g\n", r.what.c_str(), r.step.max_rel, r.step.frac_above, r.step.mean_rel, r.jitter.max_rel);
      if (r.jitter.mean_rel > 0) worst_ratio = std::max(worst_ratio, r.step.mean_rel / r.jitter.mean_rel);
      if (!r.ok) {
        ++pair_fail;
        char buf[240];
        std::snprintf(buf, sizeof buf, "%s: mean %.3g (floor %.3g), frac>1e-2 %.4f (floor %.4f), max %.3g | ", r.what.c_str(),
                      r.step.mean_rel, r.jitter.mean_rel, r.step.frac_above, r.jitter.frac_above, r.step.max_rel);
        smooth_fail.push_back(buf + stab::describe(pose));
      }
    }
  }
  all_ok = all_ok && pair_fail == 0 && wide_fail_pairs == 0;  // the image gate and, per pixel, the wide floor
  std::printf("\n## 2. Smoothness (1 cm east/north/up, 0.001 deg heading/pitch/roll)\n\n");
  std::printf("| poses | pairs | failed | worst max rel change | worst fraction > 1e-2 | worst image-mean rel change | worst step/jitter mean ratio | average jitter-floor mean | wall s |\n"
              "|---|---|---|---|---|---|---|---|---|\n| %zu | %d | %d | %.3g | %.4f | %.3g | %.3g | %.3g | %.0f |\n\n",
              sp.size(), pairs, pair_fail, worst_step, worst_frac, worst_mean, worst_ratio, sum_jitter / std::max(pairs, 1),
              seconds_since(t2));
  std::printf("Worst step: %s\n\n", worst_pose.c_str());
  std::printf("Per pixel (gated against the wide floor): s = a pixel's change, j = that pixel's own jitter-twin change (larger of\n"
              "frame_index + 1 and + 2); per-pixel criterion s <= %.3g j + %.3g. Wide floor: pairs failing it judged again with\n"
              "j_wide = the largest change to %d more twins of the base and %d twins of the perturbed pose (stab::PixelLimits).\n\n"
              "| step | pairs | fail gate (mean/fraction) | fail per-pixel | pixels over | pixels changed > %.3g with j = 0 | "
              "max s/j (j > 0) | max s/(%.3g j + %.3g) | its s, j | fail per-pixel, wide floor | pixels over it | of those j_wide = 0 |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n",
              plim.k, plim.allowance, plim.extra_twins, plim.extra_twins, plim.allowance, plim.k, plim.allowance);
  for (const Kind& k : kinds)
    std::printf("| %s | %d | %d | %d | %d | %d | %.3g | %.3g | %.3g, %.3g | %d | %d | %d |\n", k.what.c_str(), k.pairs, k.gate_fail,
                k.pixel_fail, k.pixels_over, k.no_noise, k.max_ratio, k.max_criterion, k.worst_s, k.worst_j, k.wide_fail,
                k.wide_over, k.wide_no_noise);
  std::printf("\nWorst per-pixel pair by step:\n");
  for (const Kind& k : kinds) std::printf("- %s: %s\n", k.what.c_str(), k.worst_pose.c_str());
  std::printf("\n");
  for (size_t i = 0; i < smooth_fail.size() && static_cast<int>(i) < max_listed; ++i) std::printf("- FAIL %s\n", smooth_fail[i].c_str());

  // ---- 3. uptime
  ViewRequest v;
  v.position = {47.45, 8.56, 300.0};  // below every layer, looking at the cloud bases
  v.attitude = {250.0, 10.0, 0.0};
  v.unix_time_s = *geo::parse_utc_iso8601("2026-06-06T10:00:00Z");
  v.width = w;
  v.height = h;
  const stab::UptimeLimits ulim;
  std::printf("\n## 3. Uptime (weather set at T, views at T + 600/1200/1800 s, T + 1 h, T + 30 d + 0/600/1200 s, "
              "GPU (mean of %d frames) vs CPU reference with the same anchor; GPU float noise coordinates vs double)\n\n"
              "| preset | PSNR dB baseline mean (min) | 1 h | 30 d mean (min) | max noise-coordinate error m (ratio to %.2g m + %.1g |p|) | "
              "control: reference 600 s vs 1 h, mean rel | ref clouds at 30 d | ok |\n"
              "|---|---|---|---|---|---|---|---|\n",
              ulim.gpu_frames, ulim.coord_tol_m, ulim.coord_tol_rel);
  int uptime_fail = 0;
  double uptime_worst_ratio = 0.0, uptime_worst_gap = -1e9;
  const auto t3 = Clock::now();
  for (const std::string& name : presets) {
    const weather::Weather wx = *weather::preset(name);
    const stab::UptimeResult u = stab::check_uptime(renderer, wx, v, ulim, *quality);
    double clouds30 = 0.0;
    for (const stab::UptimeCase& c : u.cases)
      if (c.group == 2) clouds30 = std::max(clouds30, c.ref_cloud_fraction);
    const bool ok = u.ok();
    uptime_fail += ok ? 0 : 1;
    uptime_worst_ratio = std::max(uptime_worst_ratio, u.max_coord_ratio);
    if (!wx.layers.empty()) uptime_worst_gap = std::max(uptime_worst_gap, u.mean_psnr[0] - u.mean_psnr[2]);
    all_ok = all_ok && ok;
    std::printf("| %s | %.2f (%.2f) | %.2f | %.2f (%.2f) | %.3g (%.2f) | %.3g | %.2f | %s |\n", name.c_str(), u.mean_psnr[0],
                u.min_psnr[0], u.mean_psnr[1], u.mean_psnr[2], u.min_psnr[2], u.max_coord_err_m, u.max_coord_ratio,
                u.drift_mean_rel, clouds30, ok ? "yes" : "NO");
  }
  const double uptime_s = seconds_since(t3);
  std::printf("\nPass: 30 d mean PSNR >= baseline mean - %.1f dB, every 1 h / 30 d case >= baseline min - %.1f dB, "
              "every noise-coordinate error within the ratio 1. %.0f s.\n",
              ulim.psnr_margin_db, ulim.psnr_margin_db, uptime_s);

  // One line to paste (docs/STABILITY.md, README): what ran, at which commit, and the result.
  std::string commit = "unknown";
#ifdef CLOUDSVC_BENCH_BIN_DIR
  if (FILE* g = popen("git -C '" CLOUDSVC_BENCH_BIN_DIR "/../..' describe --always --dirty --abbrev=7 2>/dev/null", "r")) {
    char buf[64] = {};
    if (std::fgets(buf, sizeof buf, g)) {
      commit = buf;
      while (!commit.empty() && (commit.back() == '\n' || commit.back() == '\r')) commit.pop_back();
    }
    pclose(g);
  }
#endif
  std::printf("\nSUMMARY stability commit %s seed %llu size %dx%d quality %s | globe: %lld frames, %lld failed, "
              "%lld NaN/Inf/negative values, %lld nonfinite_pixels, %lld GL errors, %lld exceptions | smoothness: %zu poses, "
              "%d pairs, %d fail the gate, %d fail per-pixel (%.3g j + %.3g), %d against the wide floor | uptime 30 d: %zu presets, %d failed, "
              "worst coordinate ratio %.2f, worst PSNR loss %.2f dB | %s\n",
              commit.c_str(), static_cast<unsigned long long>(seed), w, h, quality_name.c_str(), static_cast<long long>(frames),
              static_cast<long long>(failed), static_cast<long long>(bad_values), static_cast<long long>(nonfinite),
              static_cast<long long>(gl_errors), static_cast<long long>(exceptions), sp.size(), pairs, pair_fail,
              pixel_fail_pairs, plim.k, plim.allowance, wide_fail_pairs, presets.size(), uptime_fail, uptime_worst_ratio, uptime_worst_gap,
              all_ok ? "PASS" : "FAIL");
  std::printf("\nTotal wall time %.0f s. Result: %s\n", seconds_since(t_start), all_ok ? "PASS" : "FAIL");
  return all_ok ? 0 : 1;
}

}  // namespace cloudsvc::stability_command
