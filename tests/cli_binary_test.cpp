// End-to-end checks of the cloudsvc executable: bad input gives one line naming the flag,
// exit code 2 and no output file; a good render writes a readable EXR/PNG and prints
// the stats line.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cloudsvc_run.h"
#include "grib_test_support.h"
#include "service/demo_scenes.h"

namespace {

namespace fs = std::filesystem;

using cloudsvc::test::run_cloudsvc;
using cloudsvc::test::RunResult;

class CliBinary : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cloudsvc_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(CliBinary, BadInputGivesOneLineExitTwoAndNoFile) {
  const std::string out = (dir_ / "view.png").string();
  const std::string bad_json = (dir_ / "bad.json").string();
  std::ofstream(bad_json) << "{\"layers\": [ {\"type\": \"cumulus\", ";
  struct Case { std::vector<std::string> args; std::string flag; };
  const std::vector<Case> cases = {
      {{"--lat", "95"}, "--lat"},
      {{"--lon", "400"}, "--lon"},
      {{"--alt", "nan"}, "--alt"},
      {{"--heading", "NaN"}, "--heading"},
      {{"--alt", "-501"}, "--alt"},
      {{"--size", "0x0"}, "--size"},
      {{"--size", "8193x8193"}, "--size"},
      {{"--weather", "hurricane"}, "--weather"},
      {{"--time", "2026-13-01T00:00:00Z"}, "--time"},
      {{"--weather", (dir_ / "missing.json").string()}, "missing.json"},
      {{"--weather", bad_json}, "bad.json"},
      {{"--spp", "16"}, "--spp"},                              // only with --quality truth
      {{"--quality", "truth", "--spp", "1"}, "--spp"},         // needs two for a standard error
      {{"--quality", "truth", "--frames", "2"}, "--frames"},
      {{"--quality", "truth", "--seed", "-3"}, "--seed"},
      {{"--max-order", "2"}, "--max-order"},                  // only with --quality truth
      {{"--quality", "truth", "--max-order", "0"}, "--max-order"},
      {{"--quality", "truth", "--cumulus-domes"}, "--cumulus-domes"},  // the path tracer has no domes
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"render", "--size", "32x18", "--out", out};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const RunResult r = run_cloudsvc(args, dir_);
    EXPECT_EQ(r.exit_code, 2) << c.flag << ": " << r.err;
    EXPECT_NE(r.err.find(c.flag), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line expected: " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.flag;
  }
  const RunResult unwritable =
      run_cloudsvc({"render", "--size", "32x18", "--out", (dir_ / "no" / "such" / "dir.png").string()}, dir_);
  EXPECT_EQ(unwritable.exit_code, 2);
  EXPECT_NE(unwritable.err.find("--out"), std::string::npos) << unwritable.err;
}

TEST_F(CliBinary, RenderDrawsAForecastWhereItPutsTheCloud) {
  // Low cloud cover (GRIB2 0/6/1 on the low cloud layer) 100 % over 0-30 E, 0-60 N, with its
  // bottom and top as pressures: looking down from 4 km at 30 N 15 E, the deck fills the view.
  const fs::path grib = dir_ / "low.grib2";
  cloudsvc::test::append_cloud_field(grib, 6, 1, 214, 100.0, 0);
  cloudsvc::test::append_cloud_field(grib, 3, 0, 212, 90000.0, 0);
  cloudsvc::test::append_cloud_field(grib, 3, 0, 213, 85000.0, 0);
  const std::string out = (dir_ / "forecast.png").string();
  const std::vector<std::string> view = {"--lat", "30", "--lon", "15", "--alt", "4000", "--pitch", "-90",
                                         "--time", "2026-06-01T10:00:00Z", "--size", "48x27", "--out", out};
  std::vector<std::string> args = {"render", "--weather", grib.string()};
  args.insert(args.end(), view.begin(), view.end());
  const RunResult r = run_cloudsvc(args, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("(100.0 %)"), std::string::npos) << r.out;  // pixels with cloud
  EXPECT_TRUE(fs::exists(out));
  // Outside the forecast's area there is no cloud.
  std::vector<std::string> west = args;
  west[std::find(west.begin(), west.end(), "15") - west.begin()] = "-40";
  const RunResult clear = run_cloudsvc(west, dir_);
  ASSERT_EQ(clear.exit_code, 0) << clear.err;
  EXPECT_NE(clear.out.find(" 0 pixels with cloud"), std::string::npos) << clear.out;
  // The CPU renderers do not read forecasts; a bad forecast file names the problem.
  args.insert(args.end(), {"--quality", "reference"});
  const RunResult reference = run_cloudsvc(args, dir_);
  EXPECT_EQ(reference.exit_code, 2);
  EXPECT_NE(reference.err.find("GPU quality presets only"), std::string::npos) << reference.err;
  const fs::path text = dir_ / "bad.grib2";
  std::ofstream(text) << "nothing\n";
  const RunResult bad = run_cloudsvc({"render", "--weather", text.string(), "--out", out}, dir_);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err, "cloudsvc render: --weather " + text.string() + ": not a GRIB file (no GRIB message found)\n");
}

TEST_F(CliBinary, RenderWritesExrAndPngAndPrintsStats) {
  const std::string exr = (dir_ / "view.exr").string(), png = (dir_ / "view.png").string();
  const std::vector<std::string> pose = {"--lat", "47.45", "--lon", "8.56", "--alt", "2500", "--heading", "270",
                                         "--pitch", "5", "--roll", "0", "--time", "2026-06-21T16:30:00Z",
                                         "--fov", "60", "--size", "64x36", "--weather", "broken-cumulus"};
  for (const std::string& out : {exr, png}) {
    std::vector<std::string> args = {"render"};
    args.insert(args.end(), pose.begin(), pose.end());
    args.insert(args.end(), {"--out", out});
    const RunResult r = run_cloudsvc(args, dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("64x36"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("sun elevation"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("pixels with cloud"), std::string::npos) << r.out;
    auto in = OIIO::ImageInput::open(out);
    ASSERT_TRUE(in) << out;
    EXPECT_EQ(in->spec().width, 64);
    EXPECT_EQ(in->spec().height, 36);
    EXPECT_EQ(in->spec().nchannels, 4);
    if (out == exr) {
      EXPECT_EQ(in->spec().format, OIIO::TypeDesc::FLOAT);
    }
    in->close();
  }
  // No temporary files left behind next to the outputs.
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir_)) files += e.path().extension() == ".exr" || e.path().extension() == ".png";
  EXPECT_EQ(files, 2);
}

// `cloudsvc render --cumulus-domes`: cumulus layers drawn as individual domes; the stats
// line says how many layers the GPU drew as domes.
TEST_F(CliBinary, CumulusDomesAreDrawnWhenAskedFor) {
  const std::string out = (dir_ / "domes.exr").string();
  const std::vector<std::string> base = {"render", "--lat", "47.45", "--lon", "8.56", "--alt", "2500", "--pitch", "5",
                                         "--size", "48x27", "--weather", "scattered-cumulus", "--out", out};
  std::vector<std::string> args = base;
  args.push_back("--cumulus-domes");
  const RunResult r = run_cloudsvc(args, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("dome_layers=1"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(out));
  const RunResult plain = run_cloudsvc(base, dir_);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(plain.out.find("dome_layers"), std::string::npos) << plain.out;
}

// `cloudsvc render --quality truth`: the path-traced ground truth writes an EXR with the
// standard error as three extra channels, all finite and non-negative; its stats line
// names spp, seed and the tracer's health counters (0 lost paths, 0 majorant violations).
TEST_F(CliBinary, TruthRenderWritesStandardErrorChannels) {
  const std::string exr = (dir_ / "truth.exr").string();
  const RunResult r = run_cloudsvc({"render", "--quality", "truth", "--spp", "4", "--seed", "7", "--size", "12x7",
                                    "--alt", "600", "--pitch", "15", "--weather", "scattered-cumulus", "--out", exr},
                                   dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("spp=4 seed=7 lost_paths=0 majorant_violations=0"), std::string::npos) << r.out;
  auto in = OIIO::ImageInput::open(exr);
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  ASSERT_EQ(spec.nchannels, 7);
  EXPECT_EQ(spec.channelnames[4], "se.R");
  EXPECT_EQ(spec.channelnames[6], "se.B");
  std::vector<float> px(static_cast<std::size_t>(12 * 7 * 7));
  ASSERT_TRUE(in->read_image(0, 0, 0, 7, OIIO::TypeDesc::FLOAT, px.data()));
  int positive_error = 0;
  for (std::size_t i = 0; i < px.size(); i += 7) {
    for (int c = 0; c < 7; ++c) EXPECT_TRUE(std::isfinite(px[i + c]) && px[i + c] >= 0.0f) << "pixel " << i / 7;
    positive_error += px[i + 5] > 0.0f;
  }
  EXPECT_GT(positive_error, 12 * 7 / 2);  // a 4-path estimate is uncertain almost everywhere
}

// `--max-order N` counts only the light scattered at most N times. Under scattered cumulus
// seen from 600 m the cloud bases are lit almost wholly by multiple scattering, so with the
// same paths (same seed) the mean radiance rises with N: single scattering is well under
// half of the full estimate (about 5 % here), and three orders lie between.
TEST_F(CliBinary, TruthMaxOrderCountsOnlyTheFirstOrders) {
  auto mean_green = [&](const std::vector<std::string>& extra, const std::string& name) {
    const std::string exr = (dir_ / name).string();
    std::vector<std::string> args = {"render", "--quality", "truth",  "--spp", "4", "--seed", "7", "--size", "12x7",
                                     "--alt",  "600",      "--pitch", "15",    "--weather", "scattered-cumulus",
                                     "--out",  exr};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_cloudsvc(args, dir_);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const std::string order_tag = extra.empty() ? std::string() : std::string("max_order=").append(extra.back());
    EXPECT_NE(r.out.find(order_tag), std::string::npos) << r.out;
    auto in = OIIO::ImageInput::open(exr);
    if (!in) {
      ADD_FAILURE() << "cannot read " << exr;
      return 0.0;
    }
    std::vector<float> px(static_cast<std::size_t>(12 * 7 * 7));
    EXPECT_TRUE(in->read_image(0, 0, 0, 7, OIIO::TypeDesc::FLOAT, px.data()));
    double sum = 0.0;
    for (std::size_t i = 1; i < px.size(); i += 7) sum += px[i];
    return sum / (12 * 7);
  };
  const double single = mean_green({"--max-order", "1"}, "o1.exr");
  const double three = mean_green({"--max-order", "3"}, "o3.exr");
  const double all = mean_green({}, "all.exr");
  EXPECT_GT(single, 0.0);
  EXPECT_LT(single, three);
  EXPECT_LT(three, all);
  EXPECT_LT(single, 0.5 * all);
}

// `cloudsvc demo` at a tiny size: every documented scene is written as PNG and EXR at the
// requested size with finite, non-negative radiance, and gets its stats line.
TEST_F(CliBinary, DemoRendersEverySceneAtATinySize) {
  const fs::path out_dir = dir_ / "demo" / "nested";  // missing parents are created
  const RunResult r = run_cloudsvc({"demo", "--out-dir", out_dir.string(), "--size", "48x27"}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto& scenes = cloudsvc::demo_scenes();
  ASSERT_GE(scenes.size(), 6u);
  EXPECT_NE(r.out.find(std::to_string(scenes.size()) + " scenes at 48x27"), std::string::npos) << r.out;
  for (const auto& scene : scenes) {
    SCOPED_TRACE(scene.name);
    const fs::path png = out_dir / (scene.name + ".png"), exr = out_dir / (scene.name + ".exr");
    EXPECT_NE(r.out.find(png.string() + ": 48x27"), std::string::npos) << r.out;
    for (const fs::path& f : {png, exr}) {
      auto in = OIIO::ImageInput::open(f.string());
      ASSERT_TRUE(in) << f;
      EXPECT_EQ(in->spec().width, 48);
      EXPECT_EQ(in->spec().height, 27);
      EXPECT_EQ(in->spec().nchannels, 4);
      if (f == exr) {
        std::vector<float> px(48 * 27 * 4);
        ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, px.data()));
        int bad = 0;
        double sum = 0;
        for (float v : px) {
          bad += !std::isfinite(v) || v < 0.0f;
          sum += v;
        }
        EXPECT_EQ(bad, 0);
        EXPECT_GT(sum, 0.0);  // even the night scene is not black in linear radiance
      }
      in->close();
    }
  }
  int files = 0;
  for (const auto& e : fs::directory_iterator(out_dir)) files += e.is_regular_file();
  EXPECT_EQ(files, static_cast<int>(2 * scenes.size()));
}

TEST_F(CliBinary, HelpDocumentsUnits) {
  const RunResult r = run_cloudsvc({"render", "--help"}, dir_);
  EXPECT_EQ(r.exit_code, 0);
  for (const char* flag : {"--lat", "--lon", "--alt", "--heading", "--pitch", "--roll", "--time", "--fov", "--size",
                           "--weather", "--out", "--window"})
    EXPECT_NE(r.out.find(flag), std::string::npos) << flag;
  EXPECT_NE(r.out.find("ellipsoid"), std::string::npos);
}

// --window under a virtual X server, when xvfb-run is installed (scripts/install-deps.sh does).
TEST_F(CliBinary, WindowModeRendersUnderXvfb) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run not installed";
  const std::string cmd = "xvfb-run -a " + cloudsvc::test::shell_quote(std::string(CLOUDSVC_BIN_DIR) + "/cloudsvc") +
                          " render --window --window-frames 2 --size 64x36 --weather scattered-cumulus >" +
                          cloudsvc::test::shell_quote((dir_ / "w.txt").string()) + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream f(dir_ / "w.txt");
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  ASSERT_TRUE(WIFEXITED(status)) << text;
  EXPECT_EQ(WEXITSTATUS(status), 0) << text;
  EXPECT_NE(text.find("window: 2 frames"), std::string::npos) << text;
}

}  // namespace
