// `cloudsvc render` and `cloudsvc demo`: headless (EGL) rendering to files.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "geodesy/utc_time.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/image_output.h"
#include "service/commands.h"
#include "service/demo_scenes.h"
#include "service/window_viewer.h"
#include "weather/presets.h"

namespace cloudsvc {

namespace {

// The one-line summary every render prints.
void print_stats(const std::string& label, const FrameImage& img) {
  const double total = static_cast<double>(img.width) * img.height;
  std::printf("%s: %dx%d in %.1f ms, sun elevation %.2f deg, %lld pixels with cloud (%.1f %%), "
              "%.1f density evaluations/px\n",
              label.c_str(), img.width, img.height, img.stats.render_ms, img.stats.sun_elevation_deg,
              static_cast<long long>(img.stats.cloud_pixels), 100.0 * static_cast<double>(img.stats.cloud_pixels) / total,
              img.stats.density_evals_per_pixel);
  std::fflush(stdout);
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
  gl::EglContext context;
  CloudRenderer renderer;
  renderer.set_weather(opt.weather);
  const FrameImage img = renderer.render(view_from(opt));
  write_image(opt.out_path, img, opt.exposure_ev);
  print_stats(opt.out_path, img);
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
