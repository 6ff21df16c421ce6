// End-to-end `cloudsvc weather-info`: the JSON it prints for GRIB2 files made here and for
// the real GFS sample, and one-line errors with exit code 2 for bad files and flags.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cloudsvc_run.h"
#include "grib_test_support.h"
#include "weather/standard_atmosphere.h"

namespace {

namespace fs = std::filesystem;
using cloudsvc::test::append_cloud_field;
using cloudsvc::test::append_grib_message;
using cloudsvc::test::GribTempDir;
using cloudsvc::test::run_cloudsvc;
using cloudsvc::test::RunResult;


TEST(WeatherInfo, PrintsTheLayersAtAPointAndTime) {
  GribTempDir dir;
  const fs::path file = dir.file("f.grib2");
  append_cloud_field(file, 6, 1, 214, 30.0, 6);     // low cloud cover 30 % at 06 UTC
  append_cloud_field(file, 3, 0, 212, 90000.0, 6);  // its bottom, Pa
  append_cloud_field(file, 3, 0, 213, 85000.0, 6);  // its top, Pa
  append_cloud_field(file, 6, 1, 214, 70.0, 12);    // 70 % at 12 UTC
  append_cloud_field(file, 6, 1, 234, 20.0, 12);    // high cloud cover 20 % at 12 UTC (no altitudes)
  const RunResult r = run_cloudsvc({"weather-info", file.string(), "--at", "30,10,2026-06-01T09:00:00Z"}, dir.file(""));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["time"], "2026-06-01T09:00:00Z");
  ASSERT_EQ(j["steps"].size(), 2u);
  ASSERT_EQ(j["layers"].size(), 2u) << r.out;
  const nlohmann::json& low = j["layers"][0];
  EXPECT_EQ(low["type"], "stratocumulus");
  EXPECT_NEAR(low["coverage"].get<double>(), 0.5, 1e-3);  // halfway from 30 % to 70 %
  // The 12 UTC step has no altitudes for the low band: the 06 UTC ones hold.
  EXPECT_NEAR(low["base_m"].get<double>(), cloudsvc::weather::standard_pressure_altitude_m(90000.0), 1.0);
  EXPECT_NEAR(low["top_m"].get<double>(), cloudsvc::weather::standard_pressure_altitude_m(85000.0), 1.0);
  EXPECT_EQ(j["layers"][1]["type"], "cirrus");
  EXPECT_NEAR(j["layers"][1]["coverage"].get<double>(), 0.2, 1e-3);

  // Without a time: the first step.
  const RunResult first = run_cloudsvc({"weather-info", file.string(), "--at", "30,10"}, dir.file(""));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const nlohmann::json f = nlohmann::json::parse(first.out);
  EXPECT_EQ(f["time"], "2026-06-01T06:00:00Z");
  EXPECT_NEAR(f["layers"][0]["coverage"].get<double>(), 0.3, 1e-3);
}

TEST(WeatherInfo, ReadsTheRealGfsForecast) {
  const fs::path gfs = fs::path(CLOUDSVC_SHARED_DATA_DIR) / "grib" / "gfs-2p5deg-clouds.grib2";
  if (!fs::exists(gfs)) GTEST_SKIP() << "GFS sample not found: " << gfs;
  GribTempDir dir;
  const RunResult r = run_cloudsvc({"weather-info", gfs.string(), "--at", "47.5,7.5"}, dir.file(""));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["layers"].size(), 2u) << r.out;
  EXPECT_EQ(j["layers"][0]["type"], "stratocumulus");
  EXPECT_NEAR(j["layers"][0]["coverage"].get<double>(), 0.36, 0.006);
  EXPECT_EQ(j["layers"][1]["type"], "cirrostratus");
}

TEST(WeatherInfo, ReadsMetarReports) {
  GribTempDir dir;
  const fs::path file = dir.file("reports.txt");
  // As published (EFJY Jyvaskyla, 139 m): scattered cloud at 600 ft, overcast cumulonimbus at 2800 ft.
  std::ofstream(file) << "2026/11/09 21:20\nEFJY 092120Z AUTO 05003KT 9999 -SHRA VCSH SCT006 OVC028CB 13/13 Q1014\n";
  const RunResult r = run_cloudsvc({"weather-info", file.string(), "--at", "62.3995,25.6783"}, dir.file(""));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["time"], "2026-11-09T21:20:00Z");
  ASSERT_EQ(j["layers"].size(), 2u) << r.out;
  EXPECT_EQ(j["layers"][0]["type"], "stratus");  // 183 m above the field
  EXPECT_NEAR(j["layers"][0]["coverage"].get<double>(), 3.5 / 8, 1e-9);
  EXPECT_EQ(j["layers"][1]["type"], "cumulonimbus");
  EXPECT_NEAR(j["layers"][1]["coverage"].get<double>(), 1.0, 1e-9);
}

TEST(WeatherInfo, BadInputGivesOneLineAndExitTwo) {
  GribTempDir dir;
  const fs::path text = dir.file("report.grib2");
  std::ofstream(text) << "not a forecast\n";
  const fs::path json = dir.file("w.json");
  std::ofstream(json) << "{}\n";
  const fs::path good = dir.file("good.grib2");
  append_cloud_field(good, 6, 1, 214, 30.0, 6);
  const fs::path metar = dir.file("reports.metar");
  std::ofstream(metar) << "METAR LSZH 051150Z 24008KT 9999 BKN030 05/01 Q1021=\n";
  struct Case {
    std::vector<std::string> args;
    std::string expected;  // the whole stderr line
  };
  for (const Case& c : std::vector<Case>{
           {{"weather-info", text.string(), "--at", "1,2"},
            "cloudsvc weather-info: " + text.string() + ": not a GRIB file (no GRIB message found)"},
           {{"weather-info", json.string(), "--at", "1,2"},
            "cloudsvc weather-info: " + json.string() +
                ": not a forecast file (expected .grib2, .grb2, .grib or .grb for GRIB2, .metar or .txt for METAR "
                "reports)"},
           {{"weather-info", good.string(), metar.string(), "--at", "1,2"},
            "cloudsvc weather-info: " + metar.string() + ": GRIB2 and METAR files cannot be mixed (" + good.string() +
                " is GRIB2)"},
           {{"weather-info", dir.file("none.grib2").string(), "--at", "1,2"},
            "cloudsvc weather-info: " + dir.file("none.grib2").string() + ": cannot open: No such file or directory"},
           {{"weather-info", good.string(), "--at", "95,2"},
            "cloudsvc weather-info: --at 95,2: latitude '95' is not a number in [-90, 90] (degrees)"},
           {{"weather-info", good.string(), "--at", "1"},
            "cloudsvc weather-info: --at 1: expected LAT,LON or LAT,LON,TIME"},
           {{"weather-info", good.string(), "--at", "1,2,yesterday"}, ""},
       }) {
    const RunResult r = run_cloudsvc(c.args, dir.file(""));
    EXPECT_EQ(r.exit_code, 2) << c.args[1];
    EXPECT_TRUE(r.out.empty()) << r.out;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // one line
    if (!c.expected.empty()) {
      EXPECT_EQ(r.err, c.expected + "\n");
    }
  }
}

}  // namespace
