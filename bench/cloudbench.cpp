// cloudbench: error vs cost of the ray-march knobs against the CPU reference (issue
// "Accuracy", part 2; docs/ACCURACY.md). For each scene of the scene set (--scenes, see
// bench/bench_scenes.h: by default the eight "core" scenes of tests/fixtures/accuracy_scenes.h;
// random:SEED:N draws N unseen scenes from tests/fixtures/random_scenes.h) it renders the CPU
// reference once (cached as EXR under OUT/ref/, keyed by the full scene: view, size, weather
// and reference rays per pixel, bench_scenes.h reference_key), then for each march
// configuration renders the still view (the last frame's error is measured) and N timed
// frames (median render_ms) with the GPU renderer.
//
// Sweep (not the full product): one knob at a time around the centre (the RenderQuality
// defaults: 64 log steps, t_ref 1000 m, 6 light steps) over
//   primary steps {16, 24, 32, 48, 64, 96, 128, 192}, light steps {2, 3, 4, 6, 8, 12},
//   step distribution {uniform, log t_ref 250/1000/4000 m},
// a primary x light grid {24, 32, 48, 96} x {3, 4, 8}, the naive baseline (uniform 64
// steps, 6 light steps) and the named presets (renderer/quality_presets.h).
//
// Metrics on linear radiance with renderer/reference/image_metrics.h (the definition of
// tests/accuracy_reference_vs_gpu_test.cpp): RMSE, PSNR with the reference's peak rgb
// value, max |error|. OpenImageIO's ImageBufAlgo::compare computes the same RMSE on the rgb
// channels (checked on every row; the largest relative disagreement is reported), but its
// PSNR uses a peak of 1.0, so it is not used for PSNR.
//
// Over the scene set (issue 14; bench/scene_statistics.h), per configuration: the mean and
// the 90th percentile over scenes of the per-scene RMSE relative to the naive march's RMSE
// on that scene, of the absolute RMSE, of the opacity RMSE, of the mean relative error over
// cloud pixels (|gpu - ref| / ref per rgb channel where the reference opacity > 0.01), and
// the mean and 10th percentile of the PSNR; and whether the default preset is at or below
// the naive march for the mean and the 90th percentile.
//
// Outputs in --out DIR (default bench-out): report.csv (one row per scene x configuration),
// scenes.csv (one row per scene: its parameters), report.md, pareto_<scene>.png (log-log RMSE
// vs median ms, Pareto front joined).
//
// The error is measured at --size (the CPU reference costs ~40 ms per pixel on 2 cores
// at 8000+ density evaluations per pixel), the cost at --time-size (larger, so that the
// per-frame LUT work of ~20 ms does not hide the march cost).
//
// Usage: cloudbench [--size WxH (96x54)] [--time-size WxH (160x90)] [--out DIR] [--frames N (5)] [--quick]
//                   [--ref-samples N (3: N x N sub-pixel rays per reference pixel; 1: the pixel centre)]
//                   [--scenes core|random:SEED:N (core)]
// Modes: --cost (bench/cost_command.h), --sequence (bench/sequence_command.h), --stability
// (bench/stability_command.h), --views (bench/views_command.h), --truth (bench/truth_command.h),
// --morphology (bench/morphology_command.h).
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_scenes.h"
#include "bench/bench_util.h"
#include "bench/cost_command.h"
#include "bench/image_cache.h"
#include "bench/scene_statistics.h"
#include "bench/sequence_command.h"
#include "bench/truth_command.h"
#include "bench/stability_command.h"
#include "bench/views_command.h"
#include "bench/morphology_command.h"
#include "renderer/atmosphere_luts.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/image_metrics.h"
#include "renderer/reference/reference_renderer.h"
#include "weather/presets.h"

namespace fs = std::filesystem;
using namespace cloudsvc;

namespace {

struct Options {
  int width = 96, height = 54;   // error: GPU vs reference at this size
  int time_w = 160, time_h = 90;  // cost: the timed GPU frames are rendered at this size
  fs::path out = "bench-out";
  int frames = 5;
  bool quick = false;
  // reference rays per pixel along each axis (ReferenceSettings::pixel_samples): 3 x 3
  // stratified rays, box-averaged, i.e. the pixel's footprint (docs/ACCURACY.md)
  int ref_samples = 3;
  bench::SceneSetSpec scenes;  // --scenes: core (default) or random:SEED:N
  std::string command;
};

struct Config {
  std::string label;  // e.g. "P64 L6 O3 log1000"
  std::string group;  // centre, primary, light, distribution, grid, naive, preset:<name>
  RenderQuality q;
};

struct Row {
  std::string scene, label, group;
  RenderQuality q;
  double median_ms = 0, evals_px = 0, rmse = 0, rel_rmse = 0, psnr = 0, max_err = 0, oiio_rmse = 0;
  double texture_bytes = 0;
  double opacity_rmse = 0;      // RMSE of the opacity channel
  double opacity_bias = 0;      // mean gpu - ref opacity over the image (> 0: dilated or denser clouds)
  double cloud_rel = 0;         // mean |gpu - ref| / ref over the reference's cloud pixels (NaN: none)
  std::int64_t cloud_px = 0;    // reference pixels with opacity > 0.01
  double rmse_over_naive = 0;   // rmse / the naive row's rmse on the same scene
};

std::string knob_label(const RenderQuality& q) {
  char b[128];
  if (q.step_growth_ref_m > 0)
    std::snprintf(b, sizeof b, "P%d L%d log%.0f", q.primary_steps, q.light_steps, q.step_growth_ref_m);
  else
    std::snprintf(b, sizeof b, "P%d L%d uniform", q.primary_steps, q.light_steps);
  std::string l = b;
  if (!q.ground_shadow_map) l += " shadows/px";
  if (q.ground_shadow_map && q.light_volume) l += " lightvol";
  if (q.coverage_pyramid) l += " pyramid";
  if (q.light_march_cutoff > 0.0) l += " lightcut" + std::to_string(static_cast<int>(q.light_march_cutoff));
  if (q.long_step_factor > 1) l += " long" + std::to_string(q.long_step_factor);
  if (q.level_of_detail) l += " LOD";
  if (q.cloud_resolution_divisor > 1) l += " res1/" + std::to_string(q.cloud_resolution_divisor);
  if (q.temporal_reuse) l += " T1/" + std::to_string(q.temporal_stride * q.temporal_stride);
  if (q.footprint_jitter) l += " footprint";
  if (q.column_steps > 0) l += (q.column_volume ? " colvol" : " columns") + std::to_string(q.column_steps);
  if (q.column_steps > 0 && q.sun_slab_tilt) l += " tilt";
  return l;
}

RenderQuality knobs(int p, int l, double tref) {
  RenderQuality q;
  q.primary_steps = p;
  q.light_steps = l;
  q.step_growth_ref_m = tref;
  return q;
}

// The skips of issue 5, each alone on top of the centre, then combined.
std::vector<std::pair<std::string, RenderQuality>> skip_configs() {
  std::vector<std::pair<std::string, RenderQuality>> v;
  RenderQuality c;  // the centre march without skips
  c.long_step_factor = 1;
  c.ground_shadow_map = false;
  c.coverage_pyramid = false;
  c.light_march_cutoff = 0.0;
  auto with = [&](auto f) { RenderQuality q = c; f(q); return q; };
  v.push_back({"none", c});
  v.push_back({"ground shadow map", with([](RenderQuality& q) { q.ground_shadow_map = true; })});
  v.push_back({"light volume (with the shadow map)", with([](RenderQuality& q) { q.ground_shadow_map = true; q.light_volume = true; })});
  v.push_back({"coverage pyramid", with([](RenderQuality& q) { q.coverage_pyramid = true; })});
  v.push_back({"light-march cut-off at tau 12", with([](RenderQuality& q) { q.light_march_cutoff = 12.0; })});
  v.push_back({"long steps x2", with([](RenderQuality& q) { q.long_step_factor = 2; })});
  v.push_back({"long steps x4", with([](RenderQuality& q) { q.long_step_factor = 4; })});
  v.push_back({"LOD", with([](RenderQuality& q) { q.level_of_detail = true; })});
  v.push_back({"half resolution", with([](RenderQuality& q) { q.cloud_resolution_divisor = 2; })});
  // temporal reuse with footprint jitter, as the presets use it (each frame's sample
  // through another point of the pixel); the "at the pixel centre" rows show the jitter's share
  v.push_back({"temporal 1/1 (accumulate)", with([](RenderQuality& q) {
                 q.temporal_reuse = true; q.temporal_stride = 1; q.footprint_jitter = true; })});
  v.push_back({"temporal 1/4", with([](RenderQuality& q) {
                 q.temporal_reuse = true; q.temporal_stride = 2; q.footprint_jitter = true; })});
  v.push_back({"temporal 1/16", with([](RenderQuality& q) {
                 q.temporal_reuse = true; q.temporal_stride = 4; q.footprint_jitter = true; })});
  v.push_back({"shadow map + long x2 + temporal 1/16", with([](RenderQuality& q) {
                 q.ground_shadow_map = true; q.long_step_factor = 2; q.temporal_reuse = true; q.temporal_stride = 4;
                 q.footprint_jitter = true; })});
  v.push_back({"default + light volume", with([](RenderQuality& q) {
                 q.ground_shadow_map = true; q.light_volume = true; q.long_step_factor = 2; q.temporal_reuse = true;
                 q.temporal_stride = 4; q.fast_motion_px = 1.0; q.footprint_jitter = true; })});
  v.push_back({"temporal 1/1 at the pixel centre", with([](RenderQuality& q) {
                 q.temporal_reuse = true; q.temporal_stride = 1; })});
  v.push_back({"default at the pixel centre", with([](RenderQuality& q) {
                 q.ground_shadow_map = true; q.long_step_factor = 2; q.temporal_reuse = true;
                 q.temporal_stride = 4; q.fast_motion_px = 1.0; })});
  v.push_back({"long x4 + LOD + half res + temporal 1/4", with([](RenderQuality& q) {
                 q.ground_shadow_map = true; q.long_step_factor = 4; q.level_of_detail = true;
                 q.cloud_resolution_divisor = 2; q.temporal_reuse = true; q.temporal_stride = 2; q.footprint_jitter = true; })});
  v.push_back({"long x4 + LOD + half res + temporal 1/16", with([](RenderQuality& q) {
                 q.ground_shadow_map = true; q.long_step_factor = 4; q.level_of_detail = true;
                 q.cloud_resolution_divisor = 2; q.temporal_reuse = true; q.temporal_stride = 4; q.footprint_jitter = true; })});
  return v;
}

// The configurations, deduplicated by knobs (the first group that names a set wins; the
// presets are always listed separately so the report shows them by name).
std::vector<Config> sweep(bool quick) {
  const RenderQuality c;  // centre = RenderQuality defaults
  std::vector<Config> out;
  std::set<std::string> seen;
  auto add = [&](const std::string& group, const RenderQuality& q) {
    const std::string l = knob_label(q);
    if (seen.insert(l).second) out.push_back({l, group, q});
  };
  add("centre", c);
  add("naive", *quality_preset("naive"));
  const std::vector<int> primary = quick ? std::vector<int>{32, 128} : std::vector<int>{16, 24, 32, 48, 64, 96, 128, 192};
  const std::vector<int> light = quick ? std::vector<int>{3} : std::vector<int>{2, 3, 4, 6, 8, 12};
  const std::vector<double> tref = quick ? std::vector<double>{0.0} : std::vector<double>{0.0, 250.0, 1000.0, 4000.0};
  for (int p : primary) add("primary", knobs(p, c.light_steps, c.step_growth_ref_m));
  for (int l : light) add("light", knobs(c.primary_steps, l, c.step_growth_ref_m));
  for (double t : tref) add("distribution", knobs(c.primary_steps, c.light_steps, t));
  if (!quick)
    for (int p : {24, 32, 48, 96})
      for (int l : {3, 4, 8}) add("grid", knobs(p, l, c.step_growth_ref_m));
  for (const auto& [name, q] : skip_configs()) out.push_back({knob_label(q), "skip:" + name, q});
  // (labels of the skip rows repeat the knobs; the group names the skip)
  for (const std::string& name : quality_preset_names()) {
    if (name == "naive") continue;
    const RenderQuality q = *quality_preset(name);
    out.push_back({knob_label(q), "preset:" + name, q});
  }
  return out;
}

using bench::slug;

// ---- reference cache (bench/image_cache.h) ------------------------------------------------

using Reference = bench::CachedImage;

// The scene's reference at the error size for the light model of quality q
// (reference::same_light_model), cached under OUT/ref/ (bench/image_cache.h).
Reference reference_for(const bench::BenchScene& s, const Options& o, const RenderQuality& q) {
  const reference::ReferenceSettings m = reference::same_light_model(q);
  return bench::reference_image(s, o.out / "ref", o.width, o.height, o.ref_samples, m.column_depths, m.sun_slab_tilt);
}

// RMSE over the rgb channels computed by OpenImageIO, for the cross-check.
double oiio_rmse(const FrameImage& a, const FrameImage& b) {
  OIIO::ImageSpec spec(a.width, a.height, 4, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf A(spec, const_cast<float*>(a.rgba.data())), B(spec, const_cast<float*>(b.rgba.data()));
  const auto cr = OIIO::ImageBufAlgo::compare(A, B, 0.0f, 0.0f, OIIO::ROI(0, a.width, 0, a.height, 0, 1, 0, 3));
  return cr.rms_error;
}

// ---- Pareto front and plots ---------------------------------------------------------------

// Indices of rows on the error-vs-time Pareto front (no other row is both faster and
// more accurate), sorted by time.
std::vector<size_t> pareto(const std::vector<const Row*>& rows) {
  std::vector<size_t> idx(rows.size());
  for (size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::sort(idx.begin(), idx.end(), [&](size_t a, size_t b) {
    return rows[a]->median_ms != rows[b]->median_ms ? rows[a]->median_ms < rows[b]->median_ms : rows[a]->rmse < rows[b]->rmse;
  });
  std::vector<size_t> front;
  double best = INFINITY;
  for (size_t i : idx)
    if (rows[i]->rmse < best * (1.0 - 1e-9)) { front.push_back(i); best = rows[i]->rmse; }
  return front;
}

// Log-log scatter plot: x = median ms, y = RMSE; Pareto front joined; naive and the
// presets labelled. 600x400 RGB PNG drawn with ImageBufAlgo.
void plot(const fs::path& file, const std::string& title, const std::vector<const Row*>& rows,
          const std::vector<size_t>& front) {
  const int W = 600, H = 400, L = 70, R = 20, T = 30, B = 50;
  OIIO::ImageBuf img(OIIO::ImageSpec(W, H, 3, OIIO::TypeDesc::FLOAT));
  OIIO::ImageBufAlgo::fill(img, {1.0f, 1.0f, 1.0f});
  double x0 = INFINITY, x1 = 0, y0 = INFINITY, y1 = 0;
  for (const Row* r : rows) {
    x0 = std::min(x0, r->median_ms); x1 = std::max(x1, r->median_ms);
    y0 = std::min(y0, std::max(r->rmse, 1e-12)); y1 = std::max(y1, std::max(r->rmse, 1e-12));
  }
  auto decade_lo = [](double v) { return std::pow(10.0, std::floor(std::log10(v) * 4.0) / 4.0); };
  auto decade_hi = [](double v) { return std::pow(10.0, std::ceil(std::log10(v) * 4.0 + 1e-9) / 4.0); };
  x0 = decade_lo(x0); x1 = std::max(decade_hi(x1), x0 * 1.8);
  y0 = decade_lo(y0); y1 = std::max(decade_hi(y1), y0 * 1.8);
  auto px = [&](double v) { return L + static_cast<int>((std::log(v / x0) / std::log(x1 / x0)) * (W - L - R)); };
  auto py = [&](double v) {
    return H - B - static_cast<int>((std::log(std::max(v, 1e-12) / y0) / std::log(y1 / y0)) * (H - T - B));
  };
  const std::vector<float> black{0, 0, 0}, grey{0.8f, 0.8f, 0.8f}, blue{0.1f, 0.3f, 0.9f}, red{0.85f, 0.1f, 0.1f},
      green{0.1f, 0.6f, 0.2f};
  const std::string font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  auto text = [&](int x, int y, const std::string& s, int size, const std::vector<float>& col) {
    OIIO::ImageBufAlgo::render_text(img, x, y, s, size, font, col);
  };
  // Grid lines at 1, 2, 5 x 10^k with labels.
  for (int axis = 0; axis < 2; ++axis) {
    const double lo = axis ? y0 : x0, hi = axis ? y1 : x1;
    for (int k = static_cast<int>(std::floor(std::log10(lo))); k <= static_cast<int>(std::ceil(std::log10(hi))); ++k)
      for (double m : {1.0, 2.0, 5.0}) {
        const double v = m * std::pow(10.0, k);
        if (v < lo * 0.999 || v > hi * 1.001) continue;
        char lab[32];
        std::snprintf(lab, sizeof lab, axis ? "%.0e" : "%g", v);
        if (axis) {
          OIIO::ImageBufAlgo::render_line(img, L, py(v), W - R, py(v), grey);
          text(4, py(v) + 4, lab, 12, black);
        } else {
          OIIO::ImageBufAlgo::render_line(img, px(v), T, px(v), H - B, grey);
          text(px(v) - 8, H - B + 16, lab, 12, black);
        }
      }
  }
  OIIO::ImageBufAlgo::render_box(img, L, T, W - R, H - B, black);
  text(L, 20, title, 14, black);
  text(W / 2 - 90, H - 10, "median ms/frame (log)", 13, black);
  text(4, T - 12, "RMSE (log)", 12, black);
  for (size_t i = 1; i < front.size(); ++i)
    OIIO::ImageBufAlgo::render_line(img, px(rows[front[i - 1]]->median_ms), py(rows[front[i - 1]]->rmse),
                                    px(rows[front[i]]->median_ms), py(rows[front[i]]->rmse), blue);
  for (const Row* r : rows) {
    const bool is_preset = r->group.rfind("preset:", 0) == 0, is_naive = r->group == "naive";
    const auto& col = is_naive ? red : is_preset ? green : blue;
    const int x = px(r->median_ms), y = py(r->rmse), s = is_preset || is_naive ? 4 : 2;
    OIIO::ImageBufAlgo::render_box(img, x - s, y - s, x + s, y + s, col, is_preset || is_naive);
    if (is_naive) text(x + 6, y - 4, "naive", 12, red);
    if (is_preset && r->group != "preset:default") text(x + 6, y + 12, r->group.substr(7), 12, green);
  }
  if (!img.write(file.string())) std::fprintf(stderr, "cloudbench: cannot write %s\n", file.string().c_str());
}

// ---- main flow ---------------------------------------------------------------------------

Options parse(int argc, char** argv) {
  Options o;
  bool frames_given = false;
  for (int i = 0; i < argc; ++i) o.command += (i ? " " : "") + std::string(argv[i]);
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) { std::fprintf(stderr, "cloudbench: %s needs a value\n", a.c_str()); std::exit(2); }
      return argv[++i];
    };
    if (a == "--size") {
      if (std::sscanf(value().c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 1 || o.height < 1) {
        std::fprintf(stderr, "cloudbench: --size expects WxH\n");
        std::exit(2);
      }
    } else if (a == "--time-size") {
      if (std::sscanf(value().c_str(), "%dx%d", &o.time_w, &o.time_h) != 2 || o.time_w < 1 || o.time_h < 1) {
        std::fprintf(stderr, "cloudbench: --time-size expects WxH\n");
        std::exit(2);
      }
    } else if (a == "--out") {
      o.out = value();
    } else if (a == "--frames") {
      frames_given = true;
      o.frames = std::atoi(value().c_str());
      if (o.frames < 1) { std::fprintf(stderr, "cloudbench: --frames expects N >= 1\n"); std::exit(2); }
    } else if (a == "--quick") {
      o.quick = true;
    } else if (a == "--scenes") {
      const std::string text = value();
      const auto spec = bench::parse_scene_set(text);
      if (!spec) {
        std::fprintf(stderr,
                     "cloudbench: --scenes expects core or random:SEED:N (SEED an unsigned 64-bit decimal integer, "
                     "N in 1..%d), got '%s'\n",
                     bench::kMaxRandomScenes, text.c_str());
        std::exit(2);
      }
      o.scenes = *spec;
    } else if (a == "--ref-samples") {
      o.ref_samples = std::atoi(value().c_str());
      if (o.ref_samples < 1 || o.ref_samples > 16) {
        std::fprintf(stderr, "cloudbench: --ref-samples expects 1..16\n");
        std::exit(2);
      }
    } else {
      std::fprintf(stderr, "usage: cloudbench [--size WxH] [--time-size WxH] [--out DIR] [--frames N] [--quick] [--ref-samples N] "
                           "[--scenes core|random:SEED:N]\n");
      std::exit(a == "--help" ? 0 : 2);
    }
  }
  if (o.quick && !frames_given) o.frames = 2;  // --quick times 2 frames unless --frames says otherwise
  return o;
}

// One configuration on one scene: the view held still for kStillFrames frames (a
// temporal configuration converges over one 16-frame cycle; the others march every frame
// in full), error of the last frame at the error size; cost = median render_ms of
// o.frames frames after a first (full) frame at the time size, i.e. amortised.
constexpr int kStillFrames = 17;

Row measure(CloudRenderer& renderer, const ViewRequest& base, const Config& c, const FrameImage& ref,
            const Options& o) {
  ViewRequest v = base;
  v.reset_history = true;
  FrameImage last;
  for (int f = 0; f < kStillFrames; ++f) {
    v.frame_index = static_cast<std::uint32_t>(f);
    last = renderer.render(v, c.q);
    v.reset_history = false;
  }
  std::vector<double> ms;
  double evals = 0, bytes = 0;
  v.width = o.time_w;
  v.height = o.time_h;
  v.reset_history = true;
  v.frame_index = 0;
  renderer.render(v, c.q);  // first frame at the timing size: full march, shadow map
  v.reset_history = false;
  for (int f = 1; f <= o.frames; ++f) {
    v.frame_index = static_cast<std::uint32_t>(f);
    const FrameImage img = renderer.render(v, c.q);
    ms.push_back(img.stats.render_ms);
    evals += img.stats.density_evals_per_pixel;
    bytes = static_cast<double>(img.stats.gpu_memory_bytes);
  }
  const reference::ImageDifference d = reference::compare_images(last, ref);
  Row r;
  r.label = c.label;
  r.group = c.group;
  r.q = c.q;
  r.median_ms = bench::median(ms);
  r.evals_px = evals / o.frames;
  r.rmse = d.rmse;
  r.rel_rmse = d.relative_rmse;
  r.psnr = d.psnr_db;
  r.max_err = d.max_error;
  r.oiio_rmse = oiio_rmse(last, ref);
  r.texture_bytes = bytes;
  r.opacity_rmse = d.opacity_rmse;
  r.opacity_bias = bench::opacity_bias(last, ref);
  const bench::CloudRelativeError ce = bench::cloud_relative_error(last, ref);
  r.cloud_rel = ce.mean;
  r.cloud_px = ce.pixels;
  if (last.stats.nonfinite_pixels) std::fprintf(stderr, "cloudbench: %s: non-finite pixels\n", c.label.c_str());
  return r;
}

// A CSV number; an empty field for an undefined value (NaN), which CSV readers take as missing.
std::string csv_num(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream s;
  s.precision(9);
  s << v;
  return s.str();
}

// One row per scene x configuration. The columns after oiio_rmse (issue 14) are appended so
// that readers of the earlier columns are unaffected.
void write_csv(const fs::path& file, const std::vector<Row>& rows) {
  std::ofstream f(file);
  f << "scene,config,group,primary_steps,light_steps,step_growth_ref_m,median_ms,density_evals_per_px,"
       "texture_bytes,rmse,relative_rmse,psnr_db,max_abs_error,oiio_rmse,opacity_rmse,rmse_over_naive,cloud_pixels,"
       "cloud_relative_error,opacity_bias\n";
  for (const Row& r : rows)
    f << '"' << r.scene << "\",\"" << r.label << "\"," << r.group << ',' << r.q.primary_steps << ',' << r.q.light_steps << ','
      << r.q.step_growth_ref_m << ',' << r.median_ms << ',' << r.evals_px << ','
      << static_cast<long long>(r.texture_bytes) << ',' << r.rmse << ',' << r.rel_rmse << ',' << r.psnr << ','
      << r.max_err << ',' << r.oiio_rmse << ',' << r.opacity_rmse << ',' << csv_num(r.rmse_over_naive) << ','
      << r.cloud_px << ',' << csv_num(r.cloud_rel) << ',' << r.opacity_bias << '\n';
}

// One row per scene: its parameters (the view at the error size, the sun, the weather).
void write_scenes_csv(const fs::path& file, const std::vector<bench::BenchScene>& scenes) {
  std::ofstream f(file);
  f << "scene,lat_deg,lon_deg,alt_m,heading_deg,pitch_deg,roll_deg,fov_deg,time_utc,sun_elevation_deg,sun_azimuth_deg,"
       "inside_layer,weather\n";
  f.precision(10);
  for (const bench::BenchScene& s : scenes) {
    const ViewRequest& v = s.view;
    f << '"' << s.name << "\"," << v.position.lat_deg << ',' << v.position.lon_deg << ',' << v.position.alt_m << ','
      << v.attitude.heading_deg << ',' << v.attitude.pitch_deg << ',' << v.attitude.roll_deg << ',' << v.fov_deg << ','
      << geo::format_utc_iso8601(v.unix_time_s) << ',' << s.sun_elevation_deg << ',' << s.sun_azimuth_deg << ','
      << (s.inside_layer ? 1 : 0) << ",\"" << s.weather_label << "\"\n";
  }
}

std::string num(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// The scene set: what was drawn (seed and count for random scenes) and each scene's parameters.
std::string scenes_section(const Options& o, const std::vector<bench::BenchScene>& scenes) {
  std::ostringstream md;
  md << "## Scenes\n\n";
  if (o.scenes.random)
    md << "Random scene set: seed " << o.scenes.seed << ", N = " << o.scenes.count
       << " (`--scenes random:" << o.scenes.seed << ":" << o.scenes.count
       << "`; distribution in tests/fixtures/random_scenes.h: anywhere on the globe including the poles and the "
          "antimeridian, 0-15 km, a share inside a layer, any view direction, sun -10..90 deg and never within "
       << num("%.0f", accuracy::kSunMargin_deg) << " deg of the frame, a weather preset or random layers).\n\n";
  else
    md << "Core scene set (tests/fixtures/accuracy_scenes.h, the eight core scenes).\n\n";
  md << "| scene | lat | lon | alt m | heading | pitch | roll | fov | time UTC | sun el | sun az | inside a layer | weather |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---|---|\n";
  for (const bench::BenchScene& s : scenes) {
    const ViewRequest& v = s.view;
    md << "| " << s.name << " | " << num("%.4f", v.position.lat_deg) << " | " << num("%.4f", v.position.lon_deg) << " | "
       << num("%.0f", v.position.alt_m) << " | " << num("%.1f", v.attitude.heading_deg) << " | "
       << num("%.1f", v.attitude.pitch_deg) << " | " << num("%.1f", v.attitude.roll_deg) << " | " << num("%.1f", v.fov_deg)
       << " | " << geo::format_utc_iso8601(v.unix_time_s) << " | " << num("%.1f", s.sun_elevation_deg) << " | "
       << num("%.1f", s.sun_azimuth_deg) << " | " << (s.inside_layer ? "yes" : "") << " | " << s.weather_label << " |\n";
  }
  md << "\n";
  return md.str();
}

// Per configuration, the mean and the 90th percentile over scenes of each per-scene error
// (bench/scene_statistics.h), and whether the default preset is at or below naive.
std::string over_scenes_section(const std::vector<Config>& configs,
                                std::map<std::string, std::vector<const Row*>>& by_config) {
  auto errors_of = [&](const std::string& key) {
    std::vector<bench::SceneError> e;
    for (const Row* r : by_config[key])
      e.push_back({r->rmse, r->rmse_over_naive, r->psnr, r->opacity_rmse, r->opacity_bias, r->cloud_rel});
    return bench::over_scenes(e);
  };
  const bench::OverScenes naive = errors_of("naive|" + knob_label(*quality_preset("naive")));
  std::ostringstream md;
  md << "\n## Over scenes (per configuration)\n\n"
        "Per-scene errors aggregated over the scenes: mean and 90th percentile (p90, linear interpolation between "
        "order statistics) of RMSE / naive RMSE on the same scene, of the RMSE, of the opacity RMSE and of the mean "
        "relative error over cloud pixels (|gpu - ref| / ref per rgb channel where the reference opacity > 0.01, "
        "over the scenes that have such pixels: n cloud); PSNR mean and p10 (the value 90 % of the scenes reach); "
        "opacity bias = mean over the image of gpu - ref opacity (> 0: larger or denser silhouettes than the "
        "reference), mean and p90 over scenes. "
        "\"≤ naive\" = mean and p90 of RMSE / naive RMSE both ≤ 1.\n\n"
        "| config | group | RMSE/naive mean | RMSE/naive p90 | RMSE mean | RMSE p90 | PSNR mean dB | PSNR p10 dB | "
        "opacity RMSE mean | opacity RMSE p90 | opacity bias mean | opacity bias p90 | cloud rel. err mean | "
        "cloud rel. err p90 | n cloud | ≤ naive |\n"
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const Config& c : configs) {
    const bench::OverScenes a = errors_of(c.group + "|" + c.label);
    md << "| " << c.label << " | " << c.group << " | " << num("%.3f", a.rel_mean) << " | " << num("%.3f", a.rel_p90) << " | "
       << num("%.3e", a.rmse_mean) << " | " << num("%.3e", a.rmse_p90) << " | " << num("%.2f", a.psnr_mean) << " | "
       << num("%.2f", a.psnr_p10) << " | " << num("%.4f", a.opacity_mean) << " | " << num("%.4f", a.opacity_p90) << " | "
       << num("%+.4f", a.bias_mean) << " | " << num("%+.4f", a.bias_p90) << " | " << num("%.4f", a.cloud_mean) << " | " << num("%.4f", a.cloud_p90) << " | " << a.cloud_scenes << " | "
       << (a.rel_mean <= 1.0 && a.rel_p90 <= 1.0 ? "yes" : "no") << " |\n";
  }
  const RenderQuality dq = *quality_preset("default");
  const bench::OverScenes d = errors_of("preset:default|" + knob_label(dq));
  auto verdict = [](double a, double b) { return std::string(a <= b ? "yes" : "NO") + " (" + num("%.4g", a) + " vs " + num("%.4g", b) + ")"; };
  md << "\nDefault preset ≤ naive march over " << d.scenes << " scenes:\n\n"
     << "- RMSE / naive RMSE: mean " << verdict(d.rel_mean, 1.0) << ", p90 " << verdict(d.rel_p90, 1.0) << "\n"
     << "- RMSE: mean " << verdict(d.rmse_mean, naive.rmse_mean) << ", p90 " << verdict(d.rmse_p90, naive.rmse_p90) << "\n"
     << "- opacity RMSE: mean " << verdict(d.opacity_mean, naive.opacity_mean) << ", p90 "
     << verdict(d.opacity_p90, naive.opacity_p90) << "\n"
     << "- opacity bias (gpu - ref, > 0: larger or denser silhouettes): default mean " << num("%+.4f", d.bias_mean)
     << ", p90 " << num("%+.4f", d.bias_p90) << "; naive mean " << num("%+.4f", naive.bias_mean) << ", p90 "
     << num("%+.4f", naive.bias_p90) << "\n"
     << "- cloud relative error: mean " << verdict(d.cloud_mean, naive.cloud_mean) << ", p90 "
     << verdict(d.cloud_p90, naive.cloud_p90) << "\n"
     << "- PSNR (higher is better): mean " << (d.psnr_mean >= naive.psnr_mean ? "yes" : "NO") << " ("
     << num("%.2f", d.psnr_mean) << " vs " << num("%.2f", naive.psnr_mean) << " dB), p10 "
     << (d.psnr_p10 >= naive.psnr_p10 ? "yes" : "NO") << " (" << num("%.2f", d.psnr_p10) << " vs "
     << num("%.2f", naive.psnr_p10) << " dB)\n";
  return md.str();
}

}  // namespace

int main(int argc, char** argv) {
  // `cloudbench --stability ...`: the numerical-stability sweep (bench/stability_command.h).
  if (argc > 1 && std::string(argv[1]) == "--stability") {
    std::vector<char*> rest = {argv[0]};
    for (int i = 2; i < argc; ++i) rest.push_back(argv[i]);
    return cloudsvc::stability_command::run(static_cast<int>(rest.size()), rest.data());
  }
  // `cloudbench --cost ...`: preset cost on the scene set, no reference (bench/cost_command.h).
  if (argc > 1 && std::string(argv[1]) == "--cost") {
    std::vector<char*> rest = {argv[0]};
    for (int i = 2; i < argc; ++i) rest.push_back(argv[i]);
    return cloudsvc::cost_command::run(static_cast<int>(rest.size()), rest.data());
  }
  // `cloudbench --truth ...`: presets and the reference against the path-traced truth (bench/truth_command.h).
  if (argc > 1 && std::string(argv[1]) == "--truth") {
    std::vector<char*> rest = {argv[0]};
    for (int i = 2; i < argc; ++i) rest.push_back(argv[i]);
    return cloudsvc::truth_command::run(static_cast<int>(rest.size()), rest.data());
  }
  // `cloudbench --sequence ...`: temporal reuse on a flying camera (bench/sequence_command.h).
  if (argc > 1 && std::string(argv[1]) == "--sequence") {
    std::vector<char*> rest = {argv[0]};
    for (int i = 2; i < argc; ++i) rest.push_back(argv[i]);
    return cloudsvc::sequence_command::run(static_cast<int>(rest.size()), rest.data());
  }
  // `cloudbench --views ...`: presets on views beyond the scene set, with their cloud
  // silhouettes (bench/views_command.h).
  if (argc > 1 && std::string(argv[1]) == "--views") {
    std::vector<char*> rest = {argv[0]};
    for (int i = 2; i < argc; ++i) rest.push_back(argv[i]);
    return cloudsvc::views_command::run(static_cast<int>(rest.size()), rest.data());
  }
  // `cloudbench --morphology ...`: the presets' cloud shapes against observations
  // (bench/morphology_command.h).
  if (argc > 1 && std::string(argv[1]) == "--morphology") {
    std::vector<char*> rest = {argv[0]};
    for (int i = 2; i < argc; ++i) rest.push_back(argv[i]);
    return cloudsvc::morphology_command::run(static_cast<int>(rest.size()), rest.data());
  }
  const Options o = parse(argc, argv);
  fs::create_directories(o.out);
  const auto t_start = std::chrono::steady_clock::now();
  gl::EglContext context;
  CloudRenderer renderer;
  const std::vector<Config> configs = sweep(o.quick);
  std::vector<Row> rows;
  std::map<std::string, Reference> refs;
  const std::vector<bench::BenchScene> scenes = bench::make_scene_set(o.scenes, o.width, o.height);
  std::vector<std::string> scene_names;
  double ref_seconds = 0;
  for (const bench::BenchScene& s : scenes) {
    scene_names.push_back(s.name);
    const auto t_scene = std::chrono::steady_clock::now();
    // one reference per light model the configurations draw (column depths, tilted sun slab),
    // the default's first
    std::map<std::pair<bool, bool>, Reference> models;
    auto model_ref = [&](const RenderQuality& q) -> const Reference& {
      const reference::ReferenceSettings m = reference::same_light_model(q);
      const std::pair<bool, bool> model{m.column_depths, m.sun_slab_tilt};
      auto it = models.find(model);
      if (it != models.end()) return it->second;
      Reference ref = reference_for(s, o, q);
      std::printf("%-32s reference%s%s %s %.1f s, %.0f evals/px\n", s.name.c_str(), model.first ? " (column depths)" : "",
                  model.second ? " (tilted sun slab)" : "", ref.cached ? "(cached)" : "rendered", ref.seconds,
                  ref.evals_px);
      std::fflush(stdout);
      if (!ref.cached) ref_seconds += ref.seconds;
      return models.emplace(model, std::move(ref)).first->second;
    };
    const Reference& ref = model_ref(RenderQuality{});
    renderer.set_weather(s.weather);
    renderer.render(s.view);  // shader JIT and weather upload outside the timed frames
    const size_t first = rows.size();
    for (const Config& c : configs) {
      Row r = measure(renderer, s.view, c, model_ref(c.q).img, o);
      r.scene = s.name;
      rows.push_back(r);
    }
    // each row's RMSE relative to the naive march's on this scene
    double naive_rmse = NAN;
    for (size_t i = first; i < rows.size(); ++i)
      if (rows[i].group == "naive") naive_rmse = rows[i].rmse;
    for (size_t i = first; i < rows.size(); ++i) rows[i].rmse_over_naive = naive_rmse > 0 ? rows[i].rmse / naive_rmse : NAN;
    std::printf("%-32s %zu configurations in %.1f s\n", s.name.c_str(), configs.size(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t_scene).count());
    std::fflush(stdout);
    refs[s.name] = ref;
  }
  const double total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  write_csv(o.out / "report.csv", rows);
  write_scenes_csv(o.out / "scenes.csv", scenes);

  // report.md
  std::ostringstream md;
  md << "# cloudbench report\n\nCommand: `" << o.command << "`  \n"
     << "Error at " << o.width << "x" << o.height << " (reference: " << o.ref_samples << "x" << o.ref_samples
     << " rays per pixel), cost (median ms) at " << o.time_w << "x" << o.time_h << ", " << configs.size() << " configurations x " << scene_names.size()
     << " scenes, " << o.frames << " timed frames after a warm-up (median render_ms). Total wall time "
     << num("%.1f", total_s) << " s, of which reference renders " << num("%.1f", ref_seconds)
     << " s (0 = all cached in " << (o.out / "ref").string() << ").\n\n"
     << "Error on linear radiance of the last of " << kStillFrames
     << " frames of the still view (temporal configurations have converged by then; the others march every "
        "frame in full) vs the CPU reference of the configuration's own light model (reference::same_light_model: "
        "labels with \"columns\" or \"colvol\" against the reference of each point's own column depths, the others "
        "against the homogeneous layer's), renderer/reference/image_metrics.h (PSNR peak = the reference's "
        "largest rgb value). Cost: median render_ms of the frames after the first, so temporal reuse is "
        "amortised. GPU memory: every texture the renderer holds at the timing size (FrameStats::gpu_memory_bytes).\n\n";
  double worst_oiio = 0;
  for (const Row& r : rows)
    if (r.rmse > 0) worst_oiio = std::max(worst_oiio, std::abs(r.oiio_rmse - r.rmse) / r.rmse);
  md << "OpenImageIO ImageBufAlgo::compare RMSE on rgb agrees with image_metrics RMSE to a relative "
     << num("%.1e", worst_oiio) << " (largest over all rows).\n\n";
  md << scenes_section(o, scenes);
  md << "## References (the homogeneous layer's)\n\n| scene | reference s | evals/px |\n|---|---:|---:|\n";
  for (const auto& n : scene_names)
    md << "| " << n << " | " << num("%.1f", refs[n].seconds) << " | " << num("%.0f", refs[n].evals_px) << " |\n";

  // Aggregate over scenes: mean ms, mean evals, mean PSNR, worst PSNR.
  md << "\n## All scenes (per configuration)\n\nms = sum of the scenes' median ms; PSNR mean and min over the "
        "scenes; naive ms ratio = ms / naive ms.\n\n"
        "| config | group | sum ms | ms / naive | evals/px mean | PSNR mean dB | PSNR min dB | RMSE mean | GPU MiB |\n"
        "|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  std::map<std::string, std::vector<const Row*>> by_config, by_scene;
  for (const Row& r : rows) { by_config[r.group + "|" + r.label].push_back(&r); by_scene[r.scene].push_back(&r); }
  double naive_ms = 0;
  for (const Row& r : rows) if (r.group == "naive") naive_ms += r.median_ms;
  for (const Config& c : configs) {
    const auto& v = by_config[c.group + "|" + c.label];
    double ms = 0, ev = 0, ps = 0, pmin = INFINITY, rm = 0, mib = 0;
    for (const Row* r : v) {
      ms += r->median_ms; ev += r->evals_px; ps += r->psnr; pmin = std::min(pmin, r->psnr); rm += r->rmse;
      mib = std::max(mib, r->texture_bytes / 1048576.0);
    }
    const double n = static_cast<double>(v.size());
    md << "| " << c.label << " | " << c.group << " | " << num("%.0f", ms) << " | " << num("%.2f", ms / naive_ms) << " | "
       << num("%.1f", ev / n) << " | " << num("%.2f", ps / n) << " | " << num("%.2f", pmin) << " | " << num("%.3e", rm / n)
       << " | " << num("%.1f", mib) << " |\n";
  }

  md << over_scenes_section(configs, by_config);

  // Skips (issue 5): each against the centre configuration, per scene then summed.
  struct Totals {
    double ms = 0, rmse = 0, evals = 0;  // sum of median ms, mean RMSE, sum of density evaluations per pixel
  };
  auto totals = [&](const std::string& key) {
    Totals t;
    for (const Row* r : by_config[key]) { t.ms += r->median_ms; t.rmse += r->rmse; t.evals += r->evals_px; }
    t.rmse /= static_cast<double>(std::max<size_t>(1, by_config[key].size()));
    return t;
  };
  const std::string none_key = "skip:none|" + knob_label(skip_configs().front().second);
  const auto centre = totals(none_key);
  const auto naive = totals("naive|" + knob_label(*quality_preset("naive")));
  md << "\n## Skips\n\nEach skip of issue 5 on top of the march without skips (" << knob_label(skip_configs().front().second)
     << ", shadows marched per ground pixel), then combined. Cost saved = 1 - sum ms / its sum ms (" << num("%.0f", centre.ms)
     << " ms); error added = mean RMSE / its mean RMSE - 1; ×naive = naive sum ms / sum ms, RMSE vs naive = "
        "mean RMSE / naive mean RMSE; evals/px = density evaluations per pixel per timed frame summed over the scenes "
        "(the march's work, independent of the machine), ×naive work = naive evals / evals.\n\n"
        "| skip | sum ms | cost saved | error added | ×naive speed | RMSE / naive RMSE | PSNR min dB | evals/px | ×naive work |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Config& c : configs) {
    if (c.group.rfind("skip:", 0) != 0 && c.group.rfind("preset:", 0) != 0) continue;
    const auto t = totals(c.group + "|" + c.label);
    double pmin = INFINITY;
    for (const Row* r : by_config[c.group + "|" + c.label]) pmin = std::min(pmin, r->psnr);
    md << "| " << c.group.substr(c.group.find(':') + 1) << (c.group[0] == 'p' ? " (preset)" : "") << " | "
       << num("%.0f", t.ms) << " | " << num("%+.0f%%", 100.0 * (1.0 - t.ms / centre.ms)) << " | "
       << num("%+.1f%%", 100.0 * (t.rmse / centre.rmse - 1.0)) << " | " << num("%.1f", naive.ms / t.ms)
       << " | " << num("%.2f", t.rmse / naive.rmse) << " | " << num("%.2f", pmin) << " | " << num("%.1f", t.evals)
       << " | " << num("%.1f", naive.evals / std::max(t.evals, 1e-9)) << " |\n";
  }
  md << "\n## Per scene\n";
  for (const auto& n : scene_names) {
    const auto& v = by_scene[n];
    const std::vector<size_t> front = pareto(v);
    const std::string png = "pareto_" + slug(n) + ".png";
    plot(o.out / png, n + " (" + std::to_string(o.width) + "x" + std::to_string(o.height) + ")", v, front);
    md << "\n### " << n << "\n\n![" << n << "](" << png << ")\n\nPareto front (error vs median ms):\n\n"
       << "| config | ms | evals/px | RMSE | PSNR dB | max err |\n|---|---:|---:|---:|---:|---:|\n";
    for (size_t i : front)
      md << "| " << v[i]->label << " | " << num("%.1f", v[i]->median_ms) << " | " << num("%.1f", v[i]->evals_px) << " | "
         << num("%.3e", v[i]->rmse) << " | " << num("%.2f", v[i]->psnr) << " | " << num("%.3e", v[i]->max_err) << " |\n";
    md << "\nAll configurations:\n\n| config | group | ms | evals/px | RMSE | PSNR dB | max err |\n|---|---|---:|---:|---:|---:|---:|\n";
    for (const Row* r : v)
      md << "| " << r->label << " | " << r->group << " | " << num("%.1f", r->median_ms) << " | " << num("%.1f", r->evals_px)
         << " | " << num("%.3e", r->rmse) << " | " << num("%.2f", r->psnr) << " | " << num("%.3e", r->max_err) << " |\n";
  }
  std::ofstream(o.out / "report.md") << md.str();
  std::printf("cloudbench: %zu rows in %.1f s -> %s\n", rows.size(), total_s, o.out.string().c_str());
  return 0;
}
