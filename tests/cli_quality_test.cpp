// `cloudsvc render --quality PRESET --frames N` (issue "Accuracy", part 5): parsing and
// rejection in-process, then the executable's stats line (frame_ms=, evals_per_px=) and
// that the presets really change the march (more density evaluations for a higher preset).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "renderer/quality_presets.h"
#include "service/render_options.h"

namespace {

namespace fs = std::filesystem;
using cloudsvc::ParsedCommand;

ParsedCommand parse(std::vector<std::string> args) {
  std::vector<const char*> argv{"cloudsvc", "render", "--size", "32x18", "--out", "/tmp/cli_quality_parse.png"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  return cloudsvc::parse_command_line(static_cast<int>(argv.size()), argv.data());
}

TEST(CliQuality, DefaultsAreDefaultPresetAndOneFrame) {
  const ParsedCommand c = parse({});
  ASSERT_EQ(c.exit_code, -1) << c.error;
  EXPECT_EQ(c.render.quality, "default");
  EXPECT_EQ(c.render.frames, 1);
}

TEST(CliQuality, AcceptsEveryPresetAndReference) {
  std::vector<std::string> names = cloudsvc::quality_preset_names();
  names.push_back("reference");
  for (const std::string& n : names) {
    const ParsedCommand c = parse({"--quality", n, "--frames", "3"});
    ASSERT_EQ(c.exit_code, -1) << n << ": " << c.error;
    EXPECT_EQ(c.render.quality, n);
    EXPECT_EQ(c.render.frames, 3);
  }
}

TEST(CliQuality, RejectsBadPresetAndFrameCounts) {
  struct Case { std::vector<std::string> args; std::string flag; };
  const std::vector<Case> cases = {
      {{"--quality", "extreme"}, "--quality"}, {{"--quality", "Medium"}, "--quality"},
      {{"--quality", ""}, "--quality"},        {{"--frames", "0"}, "--frames"},
      {{"--frames", "-2"}, "--frames"},        {{"--frames", "1.5"}, "--frames"},
      {{"--frames", "100001"}, "--frames"},
  };
  for (const Case& k : cases) {
    const ParsedCommand c = parse(k.args);
    EXPECT_EQ(c.exit_code, 2) << k.args[1];
    EXPECT_NE(c.error.find(k.flag), std::string::npos) << c.error;
  }
  const ParsedCommand bad = parse({"--quality", "extreme"});
  EXPECT_NE(bad.error.find("medium"), std::string::npos) << "the message lists the presets: " << bad.error;
}

// ---- the executable ------------------------------------------------------------------------

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

RunResult run_cloudsvc(const std::vector<std::string>& args, const fs::path& dir) {
  std::string cmd = std::string(CLOUDSVC_BIN_DIR) + "/cloudsvc";
  for (const auto& a : args) cmd += " '" + a + "'";
  cmd += " >" + (dir / "o.txt").string() + " 2>" + (dir / "e.txt").string();
  const int status = std::system(cmd.c_str());
  auto slurp = [](const fs::path& p) {
    std::ifstream f(p);
    return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  };
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "o.txt"), slurp(dir / "e.txt")};
}

class CliQualityBinary : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cloudsvc_cli_quality_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// " frame_ms=<x> evals_per_px=<y>" at the end of the stats line -> {x, y}; {-1, -1} if absent.
std::pair<double, double> timing(const std::string& out) {
  static const std::regex re(R"( frame_ms=([0-9.]+) evals_per_px=([0-9.]+)\n$)");
  std::smatch m;
  if (!std::regex_search(out, m, re)) return {-1.0, -1.0};
  return {std::stod(m[1]), std::stod(m[2])};
}

TEST_F(CliQualityBinary, BadInputExitsTwoWithOneLineAndNoFile) {
  const std::string out = (dir_ / "v.png").string();
  for (const auto& [flag, value] : std::vector<std::pair<std::string, std::string>>{{"--quality", "best"}, {"--frames", "0"}}) {
    const RunResult r = run_cloudsvc({"render", "--size", "32x18", "--out", out, flag, value}, dir_);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(flag), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST_F(CliQualityBinary, StatsLineEndsWithFrameMsAndEvalsAndPresetsDiffer) {
  const std::vector<std::string> view = {"render", "--size", "48x27", "--weather", "broken-cumulus", "--alt", "500",
                                         "--pitch", "20", "--heading", "200", "--time", "2026-06-21T11:30:00Z"};
  auto run = [&](const std::string& quality, const std::string& frames) {
    std::vector<std::string> a = view;
    const std::string out = (dir_ / (quality + ".exr")).string();
    for (const std::string& s : {std::string("--quality"), quality, std::string("--frames"), frames,
                                 std::string("--out"), out})
      a.push_back(s);
    const RunResult r = run_cloudsvc(a, dir_);
    EXPECT_EQ(r.exit_code, 0) << quality << ": " << r.err;
    EXPECT_TRUE(fs::exists(out)) << quality;
    const auto t = timing(r.out);
    EXPECT_GT(t.first, 0.0) << quality << ": " << r.out;
    return t;
  };
  const auto low = run("low", "3");
  const auto high = run("high", "1");
  const auto naive = run("naive", "2");
  EXPECT_GT(low.second, 0.0);
  EXPECT_GT(high.second, low.second) << "high must march more than low";
  EXPECT_GT(naive.second, 0.0);
}

TEST_F(CliQualityBinary, ReferenceQualityRendersOnTheCpu) {
  const std::string out = (dir_ / "ref.exr").string();
  const RunResult r = run_cloudsvc({"render", "--size", "16x9", "--weather", "broken-cumulus", "--alt", "500",
                                    "--pitch", "20", "--quality", "reference", "--out", out},
                                   dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out));
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << "no warning at 16x9: " << r.err;
  EXPECT_GT(timing(r.out).second, 0.0) << r.out;
}

}  // namespace
