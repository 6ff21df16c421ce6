// Options of `cloudsvc render` and `cloudsvc demo`, parsed and fully validated before
// any rendering starts (bad input -> one-line error naming the flag and its allowed
// range, exit code 2, no output file).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geodesy/geodetic.h"
#include "renderer/model/mie_phase_table.h"
#include "service/serve_options.h"
#include "service/weather_info_options.h"
#include "weather/cloud_layer.h"
#include "weather/forecast_weather.h"

namespace cloudsvc {

struct RenderOptions {
  geo::Geodetic position{47.45, 8.56, 2500.0};  // --lat --lon (deg) --alt (m, ellipsoid)
  geo::Attitude attitude{270.0, 5.0, 0.0};       // --heading --pitch --roll (deg)
  std::string time_text = "2026-06-21T12:00:00Z";  // --time, UTC ISO 8601
  double unix_time_s = 0.0;                      // parsed --time
  double fov_deg = 60.0;                         // --fov, horizontal field of view, (0, 170]
  int width = 640;                               // --size WxH, 1..8192 each
  int height = 360;
  std::string weather_arg = "broken-cumulus";    // --weather PRESET or FILE.json
  weather::Weather weather;                      // resolved preset or loaded file; forecast
                                                 // weather: the layers of the region at
                                                 // --lat/--lon and --time (weather/forecast_frame.h)
  std::shared_ptr<const weather::ForecastWeather> forecast;  // --weather FILE.grib2|.metar|.txt
  std::string out_path = "view.png";             // --out, .exr (linear half) or .png (sRGB);
                                                 // empty with --window and no --out: no file
  bool window = false;                           // --window: interactive GLFW window
  int window_frames = 0;                         // --window-frames N: close after N frames (0 = run until closed)
  double exposure_ev = 0.0;                      // --exposure: EV offset for PNG tone mapping
  std::string quality = "default";               // --quality: a renderer/quality_presets.h name,
                                                 // "reference" (the CPU reference renderer) or
                                                 // "truth" (the path-traced ground truth)
  int spp = 64;                                  // --spp N: paths per pixel of --quality truth
  std::uint64_t seed = 1;                        // --seed N: random seed of --quality truth
  int max_order = 0;                             // --max-order N: highest scattering order the
                                                 // truth counts (1 = single scattering); 0 = all
  int frames = 1;                                // --frames N >= 1: render the view N times
                                                 // (frame_index 0..N-1), write the last frame
  bool cumulus_domes = false;                    // --cumulus-domes: cumulus layers as individual
                                                 // domes (RendererConfig::cumulus_domes; GPU
                                                 // presets and reference, not truth)
  std::optional<int> column_steps;               // --column-steps N: RenderQuality::column_steps of a
                                                 // GPU preset and the window (absent: the preset's
                                                 // own); the reference's column_depths if N > 0
                                                 // (absent: off, the default preset's model)
  bool column_march = false;                     // --column-march: with --column-steps N, march
                                                 // each lit sample's column instead of the
                                                 // column volume (RenderQuality::column_volume off)
  bool noise_tiling = false;                     // --noise-tiling: RendererConfig::noise_tiling
                                                 // (every quality, truth included)
  model::CloudPhaseModel cloud_phase = model::CloudPhaseModel::kFit;  // --cloud-phase fit|mie
};

struct DemoOptions {
  std::string out_dir = "out";  // --out-dir
  int width = 640;              // --size WxH
  int height = 360;
};

// Result of parsing a command line. exit_code >= 0 means: stop and return it (help was
// printed: 0; an error was printed to stderr: 2).
struct ParsedCommand {
  enum class Kind { None, Render, Demo, Serve, WeatherInfo } kind = Kind::None;
  RenderOptions render;
  DemoOptions demo;
  ServeOptions serve;
  WeatherInfoOptions weather_info;
  int exit_code = -1;
  std::string error;  // the one-line message printed, if exit_code == 2
};

// argv[0] is the program name; argv[1] the sub-command ("render", "demo", "serve", "weather-info").
ParsedCommand parse_command_line(int argc, const char* const* argv);

}  // namespace cloudsvc
