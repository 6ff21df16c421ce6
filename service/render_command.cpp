// `cloudsvc render` and `cloudsvc demo`: headless (EGL) rendering to files.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "geodesy/utc_time.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/image_output.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/reference_renderer.h"
#include "renderer/truth/truth_renderer.h"
#include "service/commands.h"
#include "service/demo_scenes.h"
#include "service/window_viewer.h"
#include "weather/presets.h"


namespace cloudsvc {

namespace {

// The one-line summary every render prints; `suffix` is appended before the newline.
void print_stats(const std::string& label, const FrameImage& img, const std::string& suffix = "") {
  const double total = static_cast<double>(img.width) * img.height;
  std::printf("%s: %dx%d in %.1f ms, sun elevation %.2f deg azimuth %.2f deg, %lld pixels with cloud (%.1f %%), "
              "%.1f density evaluations/px%s\n",
              label.c_str(), img.width, img.height, img.stats.render_ms, img.stats.sun_elevation_deg, img.stats.sun_azimuth_deg,
              static_cast<long long>(img.stats.cloud_pixels), 100.0 * static_cast<double>(img.stats.cloud_pixels) / total,
              img.stats.density_evals_per_pixel, suffix.c_str());
  std::fflush(stdout);
}

// Reference renders above this many pixels take minutes on 2 cores (docs/REFERENCE.md).
constexpr long kReferenceWarnPixels = 320L * 180L;

// " frame_ms=<median ms of frames 2..N, or frame 1 if N = 1> evals_per_px=<last frame's>".
std::string timing_suffix(std::vector<double> frame_ms, const FrameImage& last) {
  if (frame_ms.size() > 1) frame_ms.erase(frame_ms.begin());  // frame 1 carries shader JIT / table setup
  std::sort(frame_ms.begin(), frame_ms.end());
  const std::size_t n = frame_ms.size();
  const double median = n % 2 ? frame_ms[n / 2] : 0.5 * (frame_ms[n / 2 - 1] + frame_ms[n / 2]);
  char text[96];
  std::snprintf(text, sizeof text, " frame_ms=%.1f evals_per_px=%.1f", median, last.stats.density_evals_per_pixel);
  return text;
}

ViewRequest view_from(const RenderOptions& o) {
  ViewRequest v;
  v.position = o.position;
  v.attitude = o.attitude;
  v.unix_time_s = o.unix_time_s;
  v.fov_deg = o.fov_deg;
  v.width = o.width;
  v.height = o.height;
  return v;
}

}  // namespace

int run_render(const RenderOptions& opt) {
  if (opt.window) return run_window(opt);
  ViewRequest view = view_from(opt);
  std::vector<double> frame_ms;
  FrameImage img;
  std::string domes;  // the stats line's " dome_layers=N" (GPU with --cumulus-domes: FrameStats::dome_layers)
  if (opt.quality == "truth") {  // CPU path tracer, double precision: no GL context needed
    truth::TruthSettings settings;
    settings.spp = opt.spp;
    settings.seed = opt.seed;
    if (opt.max_order > 0) settings.tracer.max_order = opt.max_order;
    settings.cloud_phase = opt.cloud_phase;
    settings.noise_tiling = opt.noise_tiling;
    const truth::TruthImage t = truth::render_truth(view, opt.weather, settings);
    img = t.image;
    frame_ms.push_back(img.stats.render_ms);
    char suffix[160];
    std::snprintf(suffix, sizeof suffix, " spp=%d seed=%llu lost_paths=%llu majorant_violations=%llu", t.spp,
                  static_cast<unsigned long long>(opt.seed), static_cast<unsigned long long>(t.counters.lost_paths),
                  static_cast<unsigned long long>(t.counters.majorant_violations));
    const std::string orders = opt.max_order > 0 ? " max_order=" + std::to_string(opt.max_order) : "";
    write_image(opt.out_path, img, opt.exposure_ev);
    print_stats(opt.out_path, img, timing_suffix(frame_ms, img) + suffix + orders);
    return img.stats.nonfinite_pixels == 0 && t.counters.majorant_violations == 0 ? 0 : 1;
  }
  if (opt.quality == "reference") {  // CPU, double precision: no GL context needed
    if (static_cast<long>(opt.width) * opt.height > kReferenceWarnPixels) {
      std::fprintf(stderr, "cloudsvc render: warning: --quality reference at %dx%d is slow (minutes above 320x180)\n",
                   opt.width, opt.height);
    }
    reference::ReferenceSettings settings;
    settings.cumulus_domes = opt.cumulus_domes;
    settings.noise_tiling = opt.noise_tiling;
    settings.column_depths = opt.column_steps.value_or(0) > 0;
    settings.cloud_phase = opt.cloud_phase;
    for (int f = 0; f < opt.frames; ++f) {
      view.frame_index = static_cast<std::uint32_t>(f);
      img = reference::render_reference(view, opt.weather, settings);
      frame_ms.push_back(img.stats.render_ms);
    }
  } else {
    RenderQuality quality = *quality_preset(opt.quality);  // validated by the parser
    if (opt.column_steps) {
      quality.column_steps = *opt.column_steps;
      quality.column_volume = !opt.column_march;
    }
    gl::EglContext context;
    CloudRenderer renderer(renderer_config(opt));
    set_render_weather(renderer, opt);
    for (int f = 0; f < opt.frames; ++f) {
      view.frame_index = static_cast<std::uint32_t>(f);
      img = renderer.render(view, quality);
      frame_ms.push_back(img.stats.render_ms);
    }
    if (opt.cumulus_domes) domes = " dome_layers=" + std::to_string(img.stats.dome_layers);
  }
  write_image(opt.out_path, img, opt.exposure_ev);
  print_stats(opt.out_path, img, timing_suffix(frame_ms, img) + domes);
  return img.stats.nonfinite_pixels == 0 ? 0 : 1;
}

int run_demo(const DemoOptions& opt) {
  std::filesystem::create_directories(opt.out_dir);
  gl::EglContext context;
  std::printf("cloudsvc demo: %s, %zu scenes at %dx%d -> %s/\n", context.description().c_str(), demo_scenes().size(),
              opt.width, opt.height, opt.out_dir.c_str());
  CloudRenderer renderer;
  int failures = 0;
  for (const DemoScene& s : demo_scenes()) {
    renderer.set_weather(*weather::preset(s.weather));
    ViewRequest v;
    v.position = s.position;
    v.attitude = s.attitude;
    v.unix_time_s = *geo::parse_utc_iso8601(s.time_utc);
    v.fov_deg = s.fov_deg;
    v.width = opt.width;
    v.height = opt.height;
    const FrameImage img = renderer.render(v);
    const std::string base = (std::filesystem::path(opt.out_dir) / s.name).string();
    write_image(base + ".png", img);
    write_image(base + ".exr", img);
    print_stats(base + ".png", img);
    if (img.stats.nonfinite_pixels != 0) ++failures;
  }
  return failures == 0 ? 0 : 1;
}

}  // namespace cloudsvc
