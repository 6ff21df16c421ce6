#include "service/window_viewer.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "geodesy/geodetic.h"
#include "geodesy/utc_time.h"
#include "renderer/cloud_renderer.h"
#include "service/window_presenter.h"
#include "weather/forecast_frame.h"

namespace cloudsvc {

namespace {

struct ViewerState {
  ViewRequest view;
  bool dirty = true;
};

void key_callback(GLFWwindow* w, int key, int, int action, int mods) {
  if (action == GLFW_RELEASE) return;
  auto* s = static_cast<ViewerState*>(glfwGetWindowUserPointer(w));
  const double fast = (mods & GLFW_MOD_SHIFT) ? 10.0 : 1.0;
  ViewRequest& v = s->view;
  switch (key) {
    case GLFW_KEY_ESCAPE: case GLFW_KEY_Q: glfwSetWindowShouldClose(w, GLFW_TRUE); return;
    case GLFW_KEY_LEFT: v.attitude.heading_deg = std::fmod(v.attitude.heading_deg - 5.0 * fast + 360.0, 360.0); break;
    case GLFW_KEY_RIGHT: v.attitude.heading_deg = std::fmod(v.attitude.heading_deg + 5.0 * fast, 360.0); break;
    case GLFW_KEY_UP: v.attitude.pitch_deg = std::min(90.0, v.attitude.pitch_deg + 2.0 * fast); break;
    case GLFW_KEY_DOWN: v.attitude.pitch_deg = std::max(-90.0, v.attitude.pitch_deg - 2.0 * fast); break;
    case GLFW_KEY_PAGE_UP: v.position.alt_m = std::min(100000.0, v.position.alt_m + 100.0 * fast); break;
    case GLFW_KEY_PAGE_DOWN: v.position.alt_m = std::max(-500.0, v.position.alt_m - 100.0 * fast); break;
    case GLFW_KEY_W: case GLFW_KEY_S: {  // move 200 m (x10 with shift) along the heading
      const double d = (key == GLFW_KEY_W ? 200.0 : -200.0) * fast;
      const double hd = v.attitude.heading_deg * M_PI / 180.0;
      const double R = geo::gaussian_radius(v.position.lat_deg);
      v.position.lat_deg = std::clamp(v.position.lat_deg + d * std::cos(hd) / R * 180.0 / M_PI, -90.0, 90.0);
      const double c = std::max(1e-6, std::cos(v.position.lat_deg * M_PI / 180.0));
      v.position.lon_deg = geo::wrap_longitude_deg(v.position.lon_deg + d * std::sin(hd) / (R * c) * 180.0 / M_PI);
      break;
    }
    case GLFW_KEY_T: v.unix_time_s += 600.0 * fast; break;  // time of day +10 min
    case GLFW_KEY_G: v.unix_time_s -= 600.0 * fast; break;
    default: return;
  }
  s->dirty = true;
}

}  // namespace

RendererConfig renderer_config(const RenderOptions& opt) {
  RendererConfig config;
  config.cumulus_domes = opt.cumulus_domes;
  config.noise_tiling = opt.noise_tiling;
  config.cloud_phase = opt.cloud_phase;
  return config;
}

void set_render_weather(CloudRenderer& renderer, const RenderOptions& opt) {
  if (!opt.forecast) return renderer.set_weather(opt.weather);
  renderer.set_forecast(opt.weather, weather::forecast_map(*opt.forecast, opt.unix_time_s, renderer.weather_map_width(),
                                                           renderer.weather_map_height()));
}

int run_window(const RenderOptions& opt) {
  WindowPresenter window(opt.width, opt.height, "cloudsvc");
  int rc = 0;
  ViewerState state;
  state.view.position = opt.position;
  state.view.attitude = opt.attitude;
  state.view.unix_time_s = opt.unix_time_s;
  state.view.fov_deg = opt.fov_deg;
  state.view.width = opt.width;
  state.view.height = opt.height;
  glfwSetWindowUserPointer(window.window(), &state);
  glfwSetKeyCallback(window.window(), key_callback);

  CloudRenderer renderer(renderer_config(opt));
  set_render_weather(renderer, opt);
  RenderQuality quality;  // every frame marched in full (the view changes by keystrokes)
  if (opt.column_steps) {
    quality.column_steps = *opt.column_steps;
    quality.column_volume = !opt.column_march;
  }
  int frames = 0;
  std::printf("window: arrows turn/pitch, W/S move, PgUp/PgDn altitude, T/G time +-10 min, shift x10, Esc quits\n");
  while (!window.close_requested()) {
    if (state.dirty) {
      const FrameImage img = renderer.render(state.view, quality);
      if (img.stats.nonfinite_pixels != 0) rc = 1;
      window.present(img, opt.exposure_ev);
      char title[256];
      std::snprintf(title, sizeof title, "cloudsvc  %.4f %.4f %.0f m  hdg %.0f pitch %.0f  %s  %.0f ms",
                    state.view.position.lat_deg, state.view.position.lon_deg, state.view.position.alt_m,
                    state.view.attitude.heading_deg, state.view.attitude.pitch_deg,
                    geo::format_utc_iso8601(state.view.unix_time_s).c_str(), img.stats.render_ms);
      window.set_title(title);
      state.dirty = false;
      ++frames;
    }
    if (opt.window_frames > 0 && frames >= opt.window_frames) break;
    glfwWaitEventsTimeout(0.05);
    window.poll();
    if (opt.window_frames > 0) state.dirty = true;  // scripted runs redraw every loop
  }
  std::printf("window: %d frames\n", frames);
  return rc;
}

}  // namespace cloudsvc
