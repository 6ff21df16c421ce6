// Command line of `cloudsvc` (CLI11): the `render` and `demo` flags, the `serve`
// sub-command (serve_options.cpp), and the reporting of bad input. CLI11 only collects each
// flag's text and prints help; every value is then validated (common/option_values.h and
// its neighbours, shared with sim_client) so that a bad command fails before any rendering
// starts, with exactly one line on stderr naming the flag, the given value and what is
// allowed, and exit code 2.
#include "service/render_options.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "common/option_paths.h"
#include "common/option_values.h"
#include "common/option_weather.h"
#include "geodesy/geodetic.h"
#include "renderer/quality_presets.h"
#include "service/cloud_phase_option.h"
#include "service/serve_command_line.h"
#include "weather/forecast_frame.h"
#include "weather/weather_json.h"

namespace cloudsvc {
namespace {

using cli::check_output_directory;
using cli::check_output_file;
using cli::fail;
using cli::FlagError;
using cli::given;
using cli::kExitBadInput;
using cli::kExitOk;
using cli::kFieldOfView;
using cli::numeric_help;
using cli::one_line;
using cli::parse_frame_count;
using cli::parse_image_size;
using cli::parse_integer;
using cli::parse_number;
using cli::parse_time;
using cli::Range;
using cli::join;
using cli::resolve_weather_choice;
using cli::weather_flag_values;
using cli::WeatherChoice;
using cli::ServeCommandLine;
using cli::WeatherInfoCommandLine;
using cli::size_help;
using cli::weather_help;

const Range kLatitude{-90.0, 90.0, false, "degrees"};
const Range kLongitude{-180.0, 180.0, false, "degrees"};
const Range kAltitude{-500.0, 100000.0, false, "metres above the WGS84 ellipsoid"};
const Range kHeading{-360.0, 360.0, false, "degrees"};
const Range kPitch{-90.0, 90.0, false, "degrees"};
const Range kRoll{-180.0, 180.0, false, "degrees"};
const Range kExposure{-20.0, 20.0, false, "EV"};
constexpr const char* kProgram = "cloudsvc";  // prefix of every error line
constexpr int kMaxFrames = 100000;  // --frames upper bound (a benchmark, not a stream)
constexpr const char* kReferenceQuality = "reference";
constexpr const char* kTruthQuality = "truth";
constexpr int kMaxSpp = 1 << 20;  // --spp upper bound
constexpr int kMaxScatteringOrder = 1 << 20;  // --max-order upper bound (paths end far sooner)

// "naive, low, medium, high, ultra, default, reference, truth": the values of --quality.
std::string quality_names_text() {
  std::vector<std::string> names = quality_preset_names();
  names.emplace_back(kReferenceQuality);
  names.emplace_back(kTruthQuality);
  return cli::join(names, ", ");
}

// Wraps a heading in degrees into [0, 360).
double wrap_heading_deg(double heading_deg) {
  const double wrapped = std::fmod(heading_deg, 360.0);
  if (wrapped < 0.0) return wrapped + 360.0 < 360.0 ? wrapped + 360.0 : 0.0;
  return wrapped;
}

// ---------------------------------------------------------------------------------------
// Flag definitions (CLI11 collects text; common/option_values.h converts it)

// Raw text of each `render` flag, as collected by CLI11.
struct RenderArgs {
  CLI::App* command = nullptr;
  std::string lat, lon, alt, heading, pitch, roll, time, fov, size, out, frames, exposure;
  std::vector<std::string> weather;  // --weather: one preset or file, or several forecast files
  std::string quality, render_frames, spp, seed, max_order;  // --quality, --frames, --spp, --seed, --max-order
  std::string cloud_phase;                        // --cloud-phase
  std::string column_steps;                       // --column-steps
  bool window = false;
  bool cumulus_domes = false;
  bool noise_tiling = false;
  bool column_march = false;                      // --column-march
};

// Raw text of each `demo` flag.
struct DemoArgs {
  CLI::App* command = nullptr;
  std::string out_dir, size;
};

void add_position_flags(CLI::App& cmd, RenderArgs& args, const RenderOptions& defaults) {
  cmd.add_option("--lat", args.lat,
                 numeric_help("Camera geodetic latitude, north positive", kLatitude,
                              defaults.position.lat_deg))
      ->type_name("DEG");
  cmd.add_option("--lon", args.lon,
                 numeric_help("Camera longitude, east positive, normalised to [-180, 180)",
                              kLongitude, defaults.position.lon_deg))
      ->type_name("DEG");
  cmd.add_option("--alt", args.alt,
                 numeric_help("Camera height", kAltitude, defaults.position.alt_m))
      ->type_name("M");
}

void add_attitude_flags(CLI::App& cmd, RenderArgs& args, const RenderOptions& defaults) {
  cmd.add_option("--heading", args.heading,
                 numeric_help("True heading, clockwise from true north, wrapped to [0, 360)",
                              kHeading, defaults.attitude.heading_deg))
      ->type_name("DEG");
  cmd.add_option("--pitch", args.pitch,
                 numeric_help("Pitch, nose up positive", kPitch, defaults.attitude.pitch_deg))
      ->type_name("DEG");
  cmd.add_option("--roll", args.roll,
                 numeric_help("Roll, right wing down positive", kRoll, defaults.attitude.roll_deg))
      ->type_name("DEG");
}

void add_view_flags(CLI::App& cmd, RenderArgs& args, const RenderOptions& defaults) {
  cmd.add_option("--time", args.time,
                 "Date and time in UTC, ISO 8601 (YYYY-MM-DDTHH:MM[:SS[.fff]]Z or +hh:mm "
                 "offset), years 1900..2199; sets the sun position; default " +
                     defaults.time_text)
      ->type_name("UTC");
  cmd.add_option("--fov", args.fov,
                 numeric_help("Horizontal field of view", kFieldOfView, defaults.fov_deg))
      ->type_name("DEG");
  cmd.add_option("--size", args.size, size_help(defaults.width, defaults.height))
      ->type_name("WxH");
  cmd.add_option("--weather", args.weather,
                 weather_help(defaults.weather_arg, "Weather (a forecast's clouds at --lat/--lon and --time, GPU "
                                                    "presets only); several GRIB2 or METAR files may follow"))
      ->type_name("PRESET|FILE...");
}

void add_output_flags(CLI::App& cmd, RenderArgs& args, const RenderOptions& defaults) {
  cmd.add_option("--out", args.out,
                 "Output image: .png (8-bit sRGB, tone mapped) or .exr (linear 32-bit float), "
                 "extension case-insensitive; its directory must exist and be writable; "
                 "default " + defaults.out_path + " (none with --window)")
      ->type_name("FILE");
  cmd.add_flag("--window", args.window,
               "Show the view in an interactive window instead of writing a file "
               "(--out optional; needs a display)");
  cmd.add_option("--window-frames", args.frames,
                 "With --window: close after N frames (integer >= 0; 0 = run until the "
                 "window is closed); default " + std::to_string(defaults.window_frames))
      ->type_name("N");
  cmd.add_option("--exposure", args.exposure,
                 numeric_help("Exposure offset for PNG tone mapping, photographic stops",
                              kExposure, defaults.exposure_ev))
      ->type_name("EV");
}

void add_quality_flags(CLI::App& cmd, RenderArgs& args, const RenderOptions& defaults) {
  cmd.add_option("--quality", args.quality,
                 "Ray-march quality preset: one of " + quality_names_text() +
                     " (docs/ACCURACY.md: measured error and cost of each; reference = the CPU "
                     "reference renderer, slow: minutes above 320x180; truth = the path-traced ground "
                     "truth, every order of scattering, with its standard error as EXR channels "
                     "se.R/G/B: slower still, use small sizes); default " + defaults.quality)
      ->type_name("PRESET");
  cmd.add_option("--spp", args.spp,
                 "With --quality truth: paths per pixel (integer in [2, " + std::to_string(kMaxSpp) +
                     "]; the standard error falls as 1/sqrt(N)); default " + std::to_string(defaults.spp))
      ->type_name("N");
  cmd.add_option("--seed", args.seed,
                 "With --quality truth: random seed (integer in [0, 2147483647]); the image depends on it, "
                 "not on the thread count; default " + std::to_string(defaults.seed))
      ->type_name("N");
  cmd.add_option("--max-order", args.max_order,
                 "With --quality truth: count only light scattered at most N times (integer in [1, " +
                     std::to_string(kMaxScatteringOrder) + "]; 1 = single scattering; the difference "
                     "between two orders is the light of the orders between, docs/TRUTH.md); default: every order")
      ->type_name("N");
  cmd.add_option("--frames", args.render_frames,
                 "Render the same view N times (frame_index 0..N-1, integer in [1, " +
                     std::to_string(kMaxFrames) + "]) and write the last frame; the stats line's "
                     "frame_ms is the median of frames 2..N; default " + std::to_string(defaults.frames))
      ->type_name("N");
  cmd.add_flag("--cumulus-domes", args.cumulus_domes,
               "Draw cumulus layers as individual clouds (domes over a placement with a power-law spread of "
               "sizes, docs/MORPHOLOGY.md) instead of the thresholded noise field; GPU presets and --quality "
               "reference, not truth; slower on llvmpipe (docs/MORPHOLOGY.md); default off");
  cmd.add_option("--column-steps", args.column_steps,
                 "Give the diffuse light the optical depths of each point's own cloud column (the independent "
                 "column approximation, docs/RENDERING.md), from a column volume marched in N steps from each "
                 "layer's base to its top, instead of a homogeneous layer's; 0-64, GPU presets except naive, "
                 "and --window; any N > 0 makes --quality reference march the columns finely; not valid with "
                 "truth; default: the preset's own (8 marched in high and ultra, 0 = off in the others and in "
                 "--quality reference, which then draws the default preset's light model)")
      ->type_name("N");
  cmd.add_flag("--column-march", args.column_march,
               "With --column-steps N: march each lit sample's own column in N steps, as the reference does, "
               "instead of reading the column volume (exact at any distance, N density evaluations per lit sample "
               "every frame; docs/RENDERING.md \"Column volume\"); GPU presets and --window");
  cmd.add_flag("--noise-tiling", args.noise_tiling,
               "Read the cloud noise through its stochastic tiling, so the clouds do not repeat with the "
               "noise's period (4-50 km by cloud type, docs/MORPHOLOGY.md); every quality; the march costs "
               "1.4-1.7x on llvmpipe; default off");
  cmd.add_option("--cloud-phase", args.cloud_phase,
                 cloud_phase_help(defaults.cloud_phase, "the render waits for it (every quality, reference and truth too)"))
      ->type_name("MODEL");
}

void add_render_command(CLI::App& app, RenderArgs& args) {
  const RenderOptions defaults;
  args.command = app.add_subcommand(
      "render", "Render one view of the clouds to an image file (or an interactive window)");
  args.command->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  add_position_flags(*args.command, args, defaults);
  add_attitude_flags(*args.command, args, defaults);
  add_view_flags(*args.command, args, defaults);
  add_output_flags(*args.command, args, defaults);
  add_quality_flags(*args.command, args, defaults);
  args.command->footer(
      "Example:\n  cloudsvc render --lat 46.55 --lon 7.98 --alt 3500 --heading 180 "
      "--time 2026-06-21T16:00:00Z --weather scattered-cumulus --size 1280x720 --out view.exr\n"
      "Exit codes: 0 ok, 1 runtime failure (e.g. no GL context), 2 bad input.");
}

void add_demo_command(CLI::App& app, DemoArgs& args) {
  const DemoOptions defaults;
  args.command =
      app.add_subcommand("demo", "Render the documented demo scene set into a directory");
  args.command->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  args.command
      ->add_option("--out-dir", args.out_dir,
                   "Directory for the images; created if absent (its nearest existing parent "
                   "must be a writable directory); default " + defaults.out_dir)
      ->type_name("DIR");
  args.command->add_option("--size", args.size, size_help(defaults.width, defaults.height))
      ->type_name("WxH");
  args.command->footer(
      "Example:\n  cloudsvc demo --out-dir out --size 1280x720\n"
      "Exit codes: 0 ok, 1 runtime failure (e.g. no GL context), 2 bad input.");
}

void configure_app(CLI::App& app, RenderArgs& render, DemoArgs& demo) {
  app.name(kProgram);
  app.description(
      "cloudsvc: volumetric cloud renderer for flight simulators.\n"
      "Angles are degrees, altitudes metres above the WGS84 ellipsoid, times UTC.");
  app.require_subcommand(0, 1);
  app.footer(
      "Run `cloudsvc render --help`, `cloudsvc demo --help`, `cloudsvc serve --help` or "
      "`cloudsvc weather-info --help` for "
      "the flags of a sub-command.\nExit codes: 0 ok (serve: clean shutdown on SIGINT or "
      "SIGTERM), 1 runtime failure (e.g. no GL context), 2 bad input.");
  add_render_command(app, render);
  add_demo_command(app, demo);
  // `serve` is registered by cli::ServeCommandLine (serve_options.cpp) after this.
}

// ---------------------------------------------------------------------------------------
// Validation of the collected text (each flag at most once: cli::given)

void apply_geometry(const RenderArgs& a, RenderOptions& opt) {
  const CLI::App& cmd = *a.command;
  if (given(cmd, "--lat")) opt.position.lat_deg = parse_number("--lat", a.lat, kLatitude);
  if (given(cmd, "--lon")) {
    opt.position.lon_deg = geo::wrap_longitude_deg(parse_number("--lon", a.lon, kLongitude));
  }
  if (given(cmd, "--alt")) opt.position.alt_m = parse_number("--alt", a.alt, kAltitude);
  if (given(cmd, "--heading")) {
    opt.attitude.heading_deg = wrap_heading_deg(parse_number("--heading", a.heading, kHeading));
  }
  if (given(cmd, "--pitch")) opt.attitude.pitch_deg = parse_number("--pitch", a.pitch, kPitch);
  if (given(cmd, "--roll")) opt.attitude.roll_deg = parse_number("--roll", a.roll, kRoll);
  if (given(cmd, "--fov")) opt.fov_deg = parse_number("--fov", a.fov, kFieldOfView);
}

void apply_image(const RenderArgs& a, RenderOptions& opt) {
  const CLI::App& cmd = *a.command;
  if (given(cmd, "--size")) std::tie(opt.width, opt.height) = parse_image_size("--size", a.size);
  if (given(cmd, "--exposure")) opt.exposure_ev = parse_number("--exposure", a.exposure, kExposure);
  opt.window = a.window;
  if (given(cmd, "--window-frames")) {
    opt.window_frames =
        parse_frame_count("--window-frames", a.frames, "0 = until the window is closed");
    if (!opt.window) fail("--window-frames", a.frames, "only valid together with --window");
  }
}

void apply_quality(const RenderArgs& a, RenderOptions& opt) {
  const CLI::App& cmd = *a.command;
  if (given(cmd, "--quality")) {
    if (a.quality != kReferenceQuality && a.quality != kTruthQuality && !quality_preset(a.quality)) {
      fail("--quality", a.quality, "expected one of " + quality_names_text());
    }
    if (opt.window) fail("--quality", a.quality, "not valid with --window (file output only)");
    opt.quality = a.quality;
  }
  if (given(cmd, "--frames")) {
    opt.frames = parse_integer("--frames", a.render_frames, 1, kMaxFrames, "frames");
    if (opt.window) fail("--frames", a.render_frames, "not valid with --window (use --window-frames)");
    if (opt.quality == kTruthQuality) fail("--frames", a.render_frames, "not valid with --quality truth (use --spp)");
  }
  const bool truth = opt.quality == kTruthQuality;
  if (a.cumulus_domes) {
    if (truth) fail("--quality", opt.quality, "not valid with --cumulus-domes (the path tracer draws the noise field)");
    opt.cumulus_domes = true;
  }
  opt.noise_tiling = a.noise_tiling;
  if (given(cmd, "--column-steps")) {
    if (truth) fail("--column-steps", a.column_steps, "not valid with --quality truth (the path tracer follows every path)");
    opt.column_steps = parse_integer("--column-steps", a.column_steps, 0, 64, "steps");
  }
  if (a.column_march) {
    if (opt.column_steps.value_or(0) == 0)
      fail("--column-march", "given", "needs --column-steps N > 0 (the steps of each marched column)");
    opt.column_march = true;
  }
  if (given(cmd, "--cloud-phase")) {
    const std::optional<model::CloudPhaseModel> m = model::cloud_phase_model_from_name(a.cloud_phase);
    if (!m) fail("--cloud-phase", a.cloud_phase, "expected fit or mie");
    opt.cloud_phase = *m;
  }
  if (given(cmd, "--spp")) {
    opt.spp = parse_integer("--spp", a.spp, 2, kMaxSpp, "paths per pixel");
    if (!truth) fail("--spp", a.spp, "only valid with --quality truth");
  }
  if (given(cmd, "--max-order")) {
    opt.max_order = parse_integer("--max-order", a.max_order, 1, kMaxScatteringOrder, "scattering order");
    if (!truth) fail("--max-order", a.max_order, "only valid with --quality truth");
  }
  if (given(cmd, "--seed")) {
    opt.seed = static_cast<std::uint64_t>(parse_integer("--seed", a.seed, 0, std::numeric_limits<int>::max(), "seed"));
    if (!truth) fail("--seed", a.seed, "only valid with --quality truth");
  }
}

// --time, --weather and --out are resolved even when not given (their defaults are text).
void apply_scene_and_output(const RenderArgs& a, RenderOptions& opt) {
  const CLI::App& cmd = *a.command;
  if (given(cmd, "--time")) opt.time_text = a.time;
  opt.unix_time_s = parse_time("--time", opt.time_text);
  const std::vector<std::string> weather_values = weather_flag_values(cmd, a.weather, opt.weather_arg);
  opt.weather_arg = join(weather_values, " ");
  if (weather::is_forecast_path(weather_values.front()) && (opt.quality == "reference" || opt.quality == "truth"))
    fail("--weather", opt.weather_arg, "GRIB2 and METAR weather is drawn by the GPU quality presets only, not --quality " + opt.quality);
  WeatherChoice choice = resolve_weather_choice("--weather", weather_values, opt.unix_time_s);
  opt.forecast = std::move(choice.forecast);
  opt.weather = opt.forecast ? weather::forecast_weather_at(*opt.forecast, opt.position.lat_deg,
                                                            opt.position.lon_deg, opt.unix_time_s)
                             : std::move(choice.weather);
  if (given(cmd, "--out")) {
    opt.out_path = a.out;
  } else if (opt.window) {
    opt.out_path.clear();  // window only, no file
    return;
  }
  check_output_file("--out", opt.out_path);
}

RenderOptions validate_render(const RenderArgs& args) {
  RenderOptions opt;
  apply_geometry(args, opt);
  apply_image(args, opt);
  apply_quality(args, opt);
  apply_scene_and_output(args, opt);
  return opt;
}

DemoOptions validate_demo(const DemoArgs& args) {
  DemoOptions opt;
  const CLI::App& cmd = *args.command;
  if (given(cmd, "--size")) std::tie(opt.width, opt.height) = parse_image_size("--size", args.size);
  if (given(cmd, "--out-dir")) opt.out_dir = args.out_dir;
  check_output_directory("--out-dir", opt.out_dir);
  return opt;
}

// ---------------------------------------------------------------------------------------
// Reporting

// "cloudsvc render" when argv[1] names a sub-command, else "cloudsvc": the prefix of
// error lines.
std::string command_prefix(int argc, const char* const* argv) {
  if (argc > 1 && argv[1] != nullptr) {
    const std::string_view first = argv[1];
    if (first == "render" || first == "demo" || first == "serve" || first == "weather-info") {
      return std::string(kProgram) + " " + argv[1];
    }
  }
  return kProgram;
}

// Arguments CLI11 could not match, from the program and its sub-commands; flags first.
std::vector<std::string> unmatched_arguments(const CLI::App& app) {
  std::vector<std::string> flags;
  std::vector<std::string> others;
  std::vector<std::string> all = app.remaining();
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    const std::vector<std::string> extra = sub->remaining();
    all.insert(all.end(), extra.begin(), extra.end());
  }
  for (std::string& arg : all) (arg.rfind("-", 0) == 0 ? flags : others).push_back(std::move(arg));
  flags.insert(flags.end(), others.begin(), others.end());
  return flags;
}

// "<argument>: unknown flag" (or sub-command, or unexpected argument).
std::string unmatched_argument_text(const CLI::App& app, const std::string& argument) {
  if (argument.rfind("-", 0) == 0) return argument + ": unknown flag";
  if (app.get_subcommands().empty()) {
    return argument + ": unknown sub-command (expected render, demo, serve or weather-info)";
  }
  return argument + ": unexpected argument (flags take the form --name VALUE)";
}

// One line for a CLI11 parse error. Unknown flags, sub-commands and missing values are
// phrased here; any other CLI11 message is passed on (it names the flag).
std::string parse_error_text(const CLI::ParseError& e, const CLI::App& app,
                             const std::string& prefix) {
  const std::string what = e.what();
  if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr) {
    const std::vector<std::string> unmatched = unmatched_arguments(app);
    if (!unmatched.empty()) return unmatched_argument_text(app, unmatched.front());
  }
  const std::size_t colon = what.find(':');
  const bool missing_value = dynamic_cast<const CLI::ArgumentMismatch*>(&e) != nullptr &&
                             colon != std::string::npos && what.ends_with(" missing");
  if (missing_value) {
    return what.substr(0, colon) + ": missing value (see `" + prefix + " --help`)";
  }
  return what;
}

ParsedCommand report_error(ParsedCommand result, const std::string& prefix,
                           const std::string& message) {
  result.exit_code = kExitBadInput;
  result.error = one_line(prefix + ": " + message);
  std::cerr << result.error << '\n' << std::flush;
  return result;
}

ParsedCommand report_help(ParsedCommand result, const CLI::App& app) {
  std::cout << app.help() << std::flush;
  result.exit_code = kExitOk;
  return result;
}

// No sub-command: the overview on stderr, then the error line.
ParsedCommand report_missing_command(ParsedCommand result, const CLI::App& app) {
  result.exit_code = kExitBadInput;
  result.error = std::string(kProgram) + ": missing sub-command (expected render, demo, serve or weather-info)";
  std::cerr << app.help() << result.error << '\n' << std::flush;
  return result;
}

}  // namespace

ParsedCommand parse_command_line(int argc, const char* const* argv) {
  ParsedCommand result;
  const std::string prefix = command_prefix(argc, argv);
  CLI::App app;
  RenderArgs render_args;
  DemoArgs demo_args;
  configure_app(app, render_args, demo_args);
  const ServeCommandLine serve_args(app);
  const WeatherInfoCommandLine weather_info_args(app);
  try {
    if (argc > 0) app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    return report_help(std::move(result), app);
  } catch (const CLI::CallForAllHelp&) {
    return report_help(std::move(result), app);
  } catch (const CLI::ParseError& e) {
    return report_error(std::move(result), prefix, parse_error_text(e, app, prefix));
  }
  try {
    if (render_args.command->parsed()) {
      result.kind = ParsedCommand::Kind::Render;
      result.render = validate_render(render_args);
    } else if (demo_args.command->parsed()) {
      result.kind = ParsedCommand::Kind::Demo;
      result.demo = validate_demo(demo_args);
    } else if (serve_args.parsed()) {
      result.kind = ParsedCommand::Kind::Serve;
      result.serve = serve_args.validate();
    } else if (weather_info_args.parsed()) {
      result.kind = ParsedCommand::Kind::WeatherInfo;
      result.weather_info = weather_info_args.validate();
    } else {
      return report_missing_command(std::move(result), app);
    }
  } catch (const FlagError& e) {
    return report_error(std::move(result), prefix, e.what());
  }
  return result;
}

}  // namespace cloudsvc
