// Command line of `cloudsvc`: defaults, every flag's valid values, and the error contract
// (one line on stderr naming the flag, exit code 2, no output file) for bad input.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "service/render_options.h"
#include "weather/presets.h"
#include "weather/weather_json.h"
#include "cli_test_support.h"

namespace cloudsvc {
namespace {

namespace fs = std::filesystem;

using test::Outcome;
using test::run;

// Asserts the error contract: exit 2, exactly the error line on stderr, nothing on
// stdout, and the line starts with the command and names `flag`.
void expect_rejected(const std::vector<std::string>& args, const std::string& flag) {
  std::string joined;
  for (const std::string& a : args) joined += a + " ";
  SCOPED_TRACE("cloudsvc " + joined);
  const Outcome r = run(args);
  EXPECT_EQ(r.cmd.exit_code, 2);
  EXPECT_EQ(r.err, r.cmd.error + "\n");
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.cmd.error.rfind("cloudsvc " + args.front() + ": ", 0), 0u) << r.cmd.error;
  EXPECT_NE(r.cmd.error.find(flag), std::string::npos) << r.cmd.error;
}

// A successful parse: no exit code, nothing printed.
Outcome expect_accepted(const std::vector<std::string>& args) {
  std::string joined;
  for (const std::string& a : args) joined += a + " ";
  SCOPED_TRACE("cloudsvc " + joined);
  Outcome r = run(args);
  EXPECT_EQ(r.cmd.exit_code, -1) << r.cmd.error;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  return r;
}

RenderOptions render_with(const std::vector<std::string>& flags) {
  std::vector<std::string> args{"render"};
  args.insert(args.end(), flags.begin(), flags.end());
  const Outcome r = expect_accepted(args);
  EXPECT_EQ(r.cmd.kind, ParsedCommand::Kind::Render);
  return r.cmd.render;
}

void expect_render_rejected(const std::string& flag, const std::string& value) {
  expect_rejected({"render", flag, value}, flag);
}

// A fresh directory under the system temp directory, removed afterwards.
class CliOptionsTest : public testing::Test {
 protected:
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("cloudsvc_cli_" + std::to_string(getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write_file(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
    return path(name);
  }

  fs::path dir_;
};

// ---- defaults and help ---------------------------------------------------------------

TEST_F(CliOptionsTest, RenderDefaults) {
  const RenderOptions o = render_with({});
  EXPECT_DOUBLE_EQ(o.position.lat_deg, 47.45);
  EXPECT_DOUBLE_EQ(o.position.lon_deg, 8.56);
  EXPECT_DOUBLE_EQ(o.position.alt_m, 2500.0);
  EXPECT_DOUBLE_EQ(o.attitude.heading_deg, 270.0);
  EXPECT_DOUBLE_EQ(o.attitude.pitch_deg, 5.0);
  EXPECT_DOUBLE_EQ(o.attitude.roll_deg, 0.0);
  EXPECT_EQ(o.time_text, "2026-06-21T12:00:00Z");
  EXPECT_DOUBLE_EQ(o.unix_time_s, 1782043200.0);
  EXPECT_DOUBLE_EQ(o.fov_deg, 60.0);
  EXPECT_EQ(o.width, 640);
  EXPECT_EQ(o.height, 360);
  EXPECT_EQ(o.weather_arg, "broken-cumulus");
  const auto preset = weather::preset("broken-cumulus");
  ASSERT_TRUE(preset.has_value());
  EXPECT_EQ(o.weather.layers.size(), preset->layers.size());
  EXPECT_FALSE(o.weather.layers.empty());
  EXPECT_EQ(o.out_path, "view.png");
  EXPECT_FALSE(o.window);
  EXPECT_EQ(o.window_frames, 0);
  EXPECT_DOUBLE_EQ(o.exposure_ev, 0.0);
  EXPECT_FALSE(o.cumulus_domes);
  EXPECT_TRUE(render_with({"--cumulus-domes"}).cumulus_domes);
  EXPECT_TRUE(render_with({"--cumulus-domes", "--quality", "reference"}).cumulus_domes);
  EXPECT_FALSE(o.noise_tiling);
  EXPECT_TRUE(render_with({"--noise-tiling"}).noise_tiling);
  EXPECT_TRUE(render_with({"--noise-tiling", "--quality", "truth"}).noise_tiling);  // every quality
  EXPECT_FALSE(o.column_steps) << "absent: each preset's own column steps";
  EXPECT_EQ(render_with({"--column-steps", "0"}).column_steps, 0);  // given: overrides the preset's
  EXPECT_EQ(render_with({"--column-steps", "3"}).column_steps, 3);
  EXPECT_EQ(render_with({"--column-steps", "4", "--quality", "reference"}).column_steps, 4);
  for (const char* bad : {"-1", "65", "3.5", "x", ""}) expect_rejected({"render", "--column-steps", bad}, "--column-steps");
  expect_rejected({"render", "--column-steps", "3", "--quality", "truth"}, "--column-steps");
  EXPECT_FALSE(o.column_march);
  EXPECT_TRUE(render_with({"--column-steps", "8", "--column-march"}).column_march);
  expect_rejected({"render", "--column-march"}, "--column-march");
  expect_rejected({"render", "--column-steps", "0", "--column-march"}, "--column-march");
  EXPECT_EQ(o.cloud_phase, model::CloudPhaseModel::kFit);
  EXPECT_EQ(render_with({"--cloud-phase", "mie"}).cloud_phase, model::CloudPhaseModel::kMie);
  EXPECT_EQ(render_with({"--cloud-phase", "mie", "--quality", "truth"}).cloud_phase, model::CloudPhaseModel::kMie);
  EXPECT_EQ(render_with({"--cloud-phase", "fit"}).cloud_phase, model::CloudPhaseModel::kFit);
  for (const char* bad : {"Mie", "", "hg", "mie "}) expect_rejected({"render", "--cloud-phase", bad}, "--cloud-phase");
  EXPECT_FALSE(fs::exists("view.png")) << "validation must not create the output file";
}

TEST_F(CliOptionsTest, DemoDefaults) {
  const Outcome r = expect_accepted({"demo"});
  EXPECT_EQ(r.cmd.kind, ParsedCommand::Kind::Demo);
  EXPECT_EQ(r.cmd.demo.out_dir, "out");
  EXPECT_EQ(r.cmd.demo.width, 640);
  EXPECT_EQ(r.cmd.demo.height, 360);
}

TEST_F(CliOptionsTest, TopLevelHelpListsCommandsAndExitCodes) {
  for (const char* flag : {"--help", "-h"}) {
    const Outcome r = run({flag});
    EXPECT_EQ(r.cmd.exit_code, 0);
    EXPECT_TRUE(r.err.empty());
    EXPECT_NE(r.out.find("render"), std::string::npos);
    EXPECT_NE(r.out.find("demo"), std::string::npos);
    EXPECT_NE(r.out.find("Exit codes"), std::string::npos);
  }
}

TEST_F(CliOptionsTest, RenderHelpDocumentsEveryFlagWithUnits) {
  const Outcome r = run({"render", "--help"});
  EXPECT_EQ(r.cmd.exit_code, 0);
  EXPECT_TRUE(r.err.empty());
  for (const char* text :
       {"--lat", "--lon", "--alt", "--heading", "--pitch", "--roll", "--time", "--fov", "--size",
        "--weather", "--out", "--window", "--window-frames", "--exposure", "--cumulus-domes", "--noise-tiling", "--column-steps", "--cloud-phase", "glory", "[-90, 90] (degrees)",
        "[-180, 180] (degrees)", "[-500, 100000] (metres above the WGS84 ellipsoid)",
        "[-360, 360] (degrees)", "(0, 170] (degrees)", "[1, 8192]", "pixels", "[-20, 20] (EV)",
        "UTC", "ISO 8601", ".json", ".exr", ".png", "default 47.45", "broken-cumulus"}) {
    EXPECT_NE(r.out.find(text), std::string::npos) << "missing: " << text << "\n" << r.out;
  }
}

TEST_F(CliOptionsTest, DemoHelpDocumentsEveryFlag) {
  const Outcome r = run({"demo", "--help"});
  EXPECT_EQ(r.cmd.exit_code, 0);
  for (const char* text : {"--out-dir", "--size", "[1, 8192]", "pixels", "default out"}) {
    EXPECT_NE(r.out.find(text), std::string::npos) << "missing: " << text << "\n" << r.out;
  }
  EXPECT_EQ(r.out.find("--lat"), std::string::npos);
}

TEST_F(CliOptionsTest, HelpWinsOverBadValues) {
  EXPECT_EQ(run({"render", "--lat", "95", "--help"}).cmd.exit_code, 0);
}

TEST_F(CliOptionsTest, NoSubCommandPrintsHelpToStderr) {
  const Outcome r = run({});
  EXPECT_EQ(r.cmd.exit_code, 2);
  EXPECT_EQ(r.cmd.kind, ParsedCommand::Kind::None);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("render"), std::string::npos);
  EXPECT_NE(r.err.find("demo"), std::string::npos);
  EXPECT_NE(r.err.find("Exit codes"), std::string::npos);
  EXPECT_FALSE(r.cmd.error.empty());
}

TEST_F(CliOptionsTest, UnknownSubCommandIsOneLine) {
  const Outcome r = run({"bogus"});
  EXPECT_EQ(r.cmd.exit_code, 2);
  EXPECT_EQ(r.err, r.cmd.error + "\n");
  EXPECT_NE(r.cmd.error.find("bogus"), std::string::npos);
}

// ---- valid values of every render flag -------------------------------------------------

TEST_F(CliOptionsTest, PositionFlags) {
  const RenderOptions o = render_with({"--lat", "-33.9", "--lon", "151.2", "--alt", "-500"});
  EXPECT_DOUBLE_EQ(o.position.lat_deg, -33.9);
  EXPECT_DOUBLE_EQ(o.position.lon_deg, 151.2);
  EXPECT_DOUBLE_EQ(o.position.alt_m, -500.0);
  EXPECT_DOUBLE_EQ(render_with({"--lat=90", "--alt", "100000"}).position.lat_deg, 90.0);
  EXPECT_DOUBLE_EQ(render_with({"--lat", "-90"}).position.lat_deg, -90.0);
  EXPECT_DOUBLE_EQ(render_with({"--alt", "1e5"}).position.alt_m, 100000.0);
  EXPECT_DOUBLE_EQ(render_with({"--lat", "+12.5"}).position.lat_deg, 12.5);
}

TEST_F(CliOptionsTest, LongitudeIsNormalisedToHalfOpenRange) {
  EXPECT_DOUBLE_EQ(render_with({"--lon", "180"}).position.lon_deg, -180.0);
  EXPECT_DOUBLE_EQ(render_with({"--lon", "-180"}).position.lon_deg, -180.0);
  EXPECT_DOUBLE_EQ(render_with({"--lon", "179.5"}).position.lon_deg, 179.5);
  EXPECT_DOUBLE_EQ(render_with({"--lon", "-0.25"}).position.lon_deg, -0.25);
}

TEST_F(CliOptionsTest, AttitudeFlags) {
  const RenderOptions o = render_with({"--heading", "90", "--pitch", "-90", "--roll", "180"});
  EXPECT_DOUBLE_EQ(o.attitude.heading_deg, 90.0);
  EXPECT_DOUBLE_EQ(o.attitude.pitch_deg, -90.0);
  EXPECT_DOUBLE_EQ(o.attitude.roll_deg, 180.0);
  EXPECT_DOUBLE_EQ(render_with({"--roll", "-180", "--pitch", "90"}).attitude.roll_deg, -180.0);
}

TEST_F(CliOptionsTest, HeadingIsWrappedToZeroTo360) {
  EXPECT_DOUBLE_EQ(render_with({"--heading", "-90"}).attitude.heading_deg, 270.0);
  EXPECT_DOUBLE_EQ(render_with({"--heading", "360"}).attitude.heading_deg, 0.0);
  EXPECT_DOUBLE_EQ(render_with({"--heading", "-360"}).attitude.heading_deg, 0.0);
  EXPECT_DOUBLE_EQ(render_with({"--heading", "0"}).attitude.heading_deg, 0.0);
  EXPECT_DOUBLE_EQ(render_with({"--heading", "359.5"}).attitude.heading_deg, 359.5);
  const double tiny_negative = render_with({"--heading", "-1e-20"}).attitude.heading_deg;
  EXPECT_GE(tiny_negative, 0.0);
  EXPECT_LT(tiny_negative, 360.0);
}

TEST_F(CliOptionsTest, TimeFlag) {
  const RenderOptions o = render_with({"--time", "2026-03-01T10:30:00Z"});
  EXPECT_EQ(o.time_text, "2026-03-01T10:30:00Z");
  EXPECT_DOUBLE_EQ(o.unix_time_s, 1772361000.0);
  EXPECT_DOUBLE_EQ(render_with({"--time", "2026-03-01T12:30:00+02:00"}).unix_time_s,
                   1772361000.0);
}

TEST_F(CliOptionsTest, ViewAndImageFlags) {
  const RenderOptions o =
      render_with({"--fov", "170", "--size", "1x8192", "--exposure", "-20"});
  EXPECT_DOUBLE_EQ(o.fov_deg, 170.0);
  EXPECT_EQ(o.width, 1);
  EXPECT_EQ(o.height, 8192);
  EXPECT_DOUBLE_EQ(o.exposure_ev, -20.0);
  const RenderOptions p = render_with({"--fov", "0.5", "--size", "1280x720", "--exposure", "+1.5"});
  EXPECT_DOUBLE_EQ(p.fov_deg, 0.5);
  EXPECT_EQ(p.width, 1280);
  EXPECT_EQ(p.height, 720);
  EXPECT_DOUBLE_EQ(p.exposure_ev, 1.5);
  EXPECT_EQ(render_with({"--size", "8192X1"}).width, 8192);
}

TEST_F(CliOptionsTest, EveryPresetIsAccepted) {
  const std::vector<std::string> names = weather::preset_names();
  ASSERT_FALSE(names.empty());
  for (const std::string& name : names) {
    const RenderOptions o = render_with({"--weather", name});
    EXPECT_EQ(o.weather_arg, name);
    EXPECT_EQ(o.weather.layers.size(), weather::preset(name)->layers.size()) << name;
  }
}

TEST_F(CliOptionsTest, WeatherFileIsLoaded) {
  const auto overcast = weather::preset("overcast-stratus");
  ASSERT_TRUE(overcast.has_value());
  const std::string file = write_file("sky.JSON", weather::to_json(*overcast));
  const RenderOptions o = render_with({"--weather", file});
  EXPECT_EQ(o.weather_arg, file);
  ASSERT_EQ(o.weather.layers.size(), overcast->layers.size());
  ASSERT_FALSE(o.weather.layers.empty());
  EXPECT_EQ(o.weather.layers[0].type, overcast->layers[0].type);
  EXPECT_DOUBLE_EQ(o.weather.layers[0].base_m, overcast->layers[0].base_m);
}

TEST_F(CliOptionsTest, OutputFlags) {
  const std::string exr = path("view.EXR");
  EXPECT_EQ(render_with({"--out", exr}).out_path, exr);
  EXPECT_FALSE(fs::exists(exr)) << "validation must not create the output file";
  EXPECT_EQ(render_with({"--out", path("a.png")}).out_path, path("a.png"));

  const RenderOptions window = render_with({"--window", "--window-frames", "10"});
  EXPECT_TRUE(window.window);
  EXPECT_EQ(window.window_frames, 10);
  EXPECT_TRUE(window.out_path.empty()) << "--window without --out writes no file";
  EXPECT_EQ(render_with({"--window", "--out", exr}).out_path, exr);
  EXPECT_EQ(render_with({"--window", "--window-frames", "0"}).window_frames, 0);
}

// ---- bad render input --------------------------------------------------------------------

TEST_F(CliOptionsTest, OutOfRangeNumbers) {
  expect_render_rejected("--lat", "95");
  expect_render_rejected("--lat", "-90.0001");
  expect_render_rejected("--lon", "400");
  expect_render_rejected("--lon", "-180.5");
  expect_render_rejected("--alt", "-501");
  expect_render_rejected("--alt", "100001");
  expect_render_rejected("--heading", "360.5");
  expect_render_rejected("--heading", "-720");
  expect_render_rejected("--pitch", "90.1");
  expect_render_rejected("--roll", "-181");
  expect_render_rejected("--fov", "0");
  expect_render_rejected("--fov", "170.01");
  expect_render_rejected("--exposure", "21");
  expect_render_rejected("--window-frames", "-1");
}

TEST_F(CliOptionsTest, LatitudeMessageFollowsTheContract) {
  const Outcome r = run({"render", "--lat", "95"});
  EXPECT_EQ(r.cmd.error, "cloudsvc render: --lat 95: out of range [-90, 90] (degrees)");
  EXPECT_EQ(r.err, "cloudsvc render: --lat 95: out of range [-90, 90] (degrees)\n");
}

TEST_F(CliOptionsTest, NonFiniteAndNonNumericValuesInEveryNumericFlag) {
  for (const char* flag : {"--lat", "--lon", "--alt", "--heading", "--pitch", "--roll", "--fov",
                           "--exposure", "--window-frames"}) {
    for (const char* value : {"nan", "NaN", "inf", "-inf", "infinity", "abc", "", "1.5.2",
                              "12abc", " 5", "0x10", "1e999"}) {
      std::vector<std::string> args{"render", flag, value};
      if (std::string(flag) == "--window-frames") args.push_back("--window");
      expect_rejected(args, flag);
    }
  }
  expect_render_rejected("--window-frames", "2.5");
  expect_render_rejected("--window-frames", "99999999999");
}

TEST_F(CliOptionsTest, BadSizes) {
  for (const char* value : {"0x0", "8193x100", "100x8193", "640", "640x", "x360", "axb", "-5x5",
                            "5x-5", "nanxnan", "640x360x2", "1.5x2", "+5x5", "99999999999x5"}) {
    expect_render_rejected("--size", value);
    expect_rejected({"demo", "--size", value}, "--size");
  }
}

TEST_F(CliOptionsTest, BadTimes) {
  for (const char* value :
       {"2026-13-01T00:00Z", "yesterday", "2026-04-31T00:00:00Z", "2026-06-21", ""}) {
    expect_render_rejected("--time", value);
  }
}

TEST_F(CliOptionsTest, BadWeather) {
  expect_render_rejected("--weather", "no-such-preset");
  expect_render_rejected("--weather", path("missing.json"));
  expect_render_rejected("--weather", write_file("broken.json", "{ \"layers\": [ {"));
  expect_render_rejected("--weather", write_file("wrong.json", "[1, 2, 3]"));
  fs::create_directory(path("dir.json"));
  expect_render_rejected("--weather", path("dir.json"));
}

TEST_F(CliOptionsTest, BadOutputPaths) {
  expect_render_rejected("--out", "/proc/x.png");
  expect_render_rejected("--out", path("no/such/dir/x.png"));
  expect_render_rejected("--out", path("view.jpg"));
  expect_render_rejected("--out", path("view"));
  expect_render_rejected("--out", path(".png"));
  expect_render_rejected("--out", "");
  write_file("plain.txt", "x");
  expect_render_rejected("--out", path("plain.txt/x.png"));
  fs::create_directory(path("dir.png"));
  expect_render_rejected("--out", path("dir.png"));
}

TEST_F(CliOptionsTest, WindowFramesNeedsWindow) {
  expect_render_rejected("--window-frames", "5");
}

TEST_F(CliOptionsTest, UnknownAndMalformedFlags) {
  expect_rejected({"render", "--foo", "1"}, "--foo");
  EXPECT_EQ(run({"render", "--foo", "1"}).cmd.error, "cloudsvc render: --foo: unknown flag");
  EXPECT_EQ(run({"--foo"}).cmd.error, "cloudsvc: --foo: unknown flag");
  expect_rejected({"render", "-x"}, "-x");
  expect_rejected({"render", "--lat=1", "--lat", "2"}, "more than once");
  expect_rejected({"render", "--out="}, "--out");
  expect_rejected({"render", "--lat"}, "--lat");
  expect_rejected({"render", "--lat", "1", "--lat", "2"}, "--lat");
  expect_rejected({"render", "stray"}, "stray");
  expect_rejected({"demo", "--lat", "1"}, "--lat");
}

TEST_F(CliOptionsTest, BadCommandCreatesNoOutputFile) {
  const std::string out = path("never.png");
  const Outcome r = run({"render", "--out", out, "--lat", "95"});
  EXPECT_EQ(r.cmd.exit_code, 2);
  EXPECT_FALSE(fs::exists(out));
}

// ---- demo -------------------------------------------------------------------------------

TEST_F(CliOptionsTest, DemoFlags) {
  const std::string nested = path("a/b/c");
  const Outcome r = expect_accepted({"demo", "--out-dir", nested, "--size", "320x200"});
  EXPECT_EQ(r.cmd.demo.out_dir, nested);
  EXPECT_EQ(r.cmd.demo.width, 320);
  EXPECT_EQ(r.cmd.demo.height, 200);
  EXPECT_FALSE(fs::exists(nested)) << "the renderer, not the parser, creates the directory";
  EXPECT_EQ(expect_accepted({"demo", "--out-dir", dir_.string()}).cmd.demo.out_dir,
            dir_.string());
}

TEST_F(CliOptionsTest, BadDemoOutputDirectories) {
  const std::string file = write_file("file.txt", "x");
  expect_rejected({"demo", "--out-dir", file}, "--out-dir");
  expect_rejected({"demo", "--out-dir", file + "/sub"}, "--out-dir");
  expect_rejected({"demo", "--out-dir", "/proc/cloudsvc-demo"}, "--out-dir");
  expect_rejected({"demo", "--out-dir", ""}, "--out-dir");
}

}  // namespace
}  // namespace cloudsvc
