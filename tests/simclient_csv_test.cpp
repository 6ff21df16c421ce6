// CSV pose-log reader: header, both time forms, extra columns, comments, quoting, and
// every error with its file:line.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geodesy/utc_time.h"
#include "sim_client/csv_reader.h"
#include "sim_client/flight_log_error.h"
#include "sim_client/replay_poses.h"

namespace {

using cloudsvc::geo::parse_utc_iso8601;
using cloudsvc::sim::FlightLogError;
using cloudsvc::sim::parse_csv;
using cloudsvc::sim::PoseTrack;

std::string join(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& l : lines) text += l + "\n";
  return text;
}

double utc(const char* iso) { return parse_utc_iso8601(iso).value(); }

void expect_error(const std::string& text, const std::string& prefix, const std::string& fragment) {
  try {
    parse_csv(text, "poses.csv");
    ADD_FAILURE() << "no error; expected " << prefix << " ... " << fragment;
  } catch (const FlightLogError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

const std::string kHeader = "time,lat,lon,alt,heading,pitch,roll";

TEST(CsvReader, BothTimeFormsCommentsAndWrapping) {
  const std::string text = join({
      "# exported from a test rig",
      kHeader,
      "2024-05-01T12:00:00Z,47.45,8.56,2500,270,5,0",
      "",
      "  # a comment between rows",
      "1714564801.5,47.4501,8.5598,2501,-10,-3,190",
      "2024-05-01T12:00:02.25Z,-47.5,-179.5,-20,360,90,-180",
      "2024-05-01T14:00:03+02:00,0,180,0,0,-90,0",
  });
  const PoseTrack t = parse_csv(text, "poses.csv");
  EXPECT_EQ(t.source, "poses.csv");
  ASSERT_EQ(t.samples.size(), 4u);
  EXPECT_DOUBLE_EQ(t.samples[0].unix_time_s, utc("2024-05-01T12:00:00Z"));
  EXPECT_DOUBLE_EQ(t.samples[0].position.lat_deg, 47.45);
  EXPECT_DOUBLE_EQ(t.samples[0].position.lon_deg, 8.56);
  EXPECT_DOUBLE_EQ(t.samples[0].position.alt_m, 2500.0);
  EXPECT_DOUBLE_EQ(t.samples[0].attitude.heading_deg, 270.0);
  EXPECT_DOUBLE_EQ(t.samples[0].attitude.pitch_deg, 5.0);
  EXPECT_FALSE(t.samples[0].velocity_enu_mps.has_value());
  // 1714564801.5 = 2024-05-01T12:00:01.5Z
  EXPECT_DOUBLE_EQ(t.samples[1].unix_time_s, utc("2024-05-01T12:00:01Z") + 0.5);
  EXPECT_DOUBLE_EQ(t.samples[1].attitude.heading_deg, 350.0);
  EXPECT_DOUBLE_EQ(t.samples[1].attitude.roll_deg, -170.0);
  EXPECT_DOUBLE_EQ(t.samples[2].unix_time_s, utc("2024-05-01T12:00:02Z") + 0.25);
  EXPECT_DOUBLE_EQ(t.samples[2].attitude.heading_deg, 0.0);
  EXPECT_DOUBLE_EQ(t.samples[2].attitude.roll_deg, -180.0);
  EXPECT_DOUBLE_EQ(t.samples[3].unix_time_s, utc("2024-05-01T12:00:03Z"));
  EXPECT_DOUBLE_EQ(t.samples[3].position.lon_deg, -180.0);  // 180 is -180 in [-180, 180)
}

TEST(CsvReader, ColumnsInAnyOrderWithExtrasAndQuotes) {
  const std::string text = join({
      " Roll ,note,TIME,Lat,lon,ALT,heading,pitch,speed",
      "1.5,\"turn, then climb\",100,10,20,30,40,2,55",
      "-1.5,\"say \"\"hi\"\"\",101,10.5,20.5,31,41,3,56",
  });
  const PoseTrack t = parse_csv(text, "poses.csv");
  ASSERT_EQ(t.samples.size(), 2u);
  EXPECT_DOUBLE_EQ(t.samples[0].unix_time_s, 100.0);
  EXPECT_DOUBLE_EQ(t.samples[0].position.lat_deg, 10.0);
  EXPECT_DOUBLE_EQ(t.samples[0].position.lon_deg, 20.0);
  EXPECT_DOUBLE_EQ(t.samples[0].position.alt_m, 30.0);
  EXPECT_DOUBLE_EQ(t.samples[0].attitude.heading_deg, 40.0);
  EXPECT_DOUBLE_EQ(t.samples[0].attitude.pitch_deg, 2.0);
  EXPECT_DOUBLE_EQ(t.samples[0].attitude.roll_deg, 1.5);
  EXPECT_DOUBLE_EQ(t.samples[1].attitude.roll_deg, -1.5);
  EXPECT_DOUBLE_EQ(t.samples[1].position.lat_deg, 10.5);
}

TEST(CsvReader, HeaderErrors) {
  expect_error(join({"# only comments", ""}), "poses.csv:2: ", "missing header row");
  expect_error(join({"100,10,20,30,40,2,1"}), "poses.csv:1: ",
               "missing header row time,lat,lon,alt,heading,pitch,roll: no column "
               "time,lat,lon,alt,heading,pitch,roll");
  expect_error(join({"time,lat,lon,alt,heading", "100,1,2,3,4"}), "poses.csv:1: ",
               "no column pitch,roll");
  expect_error(join({"time,lat,lon,alt,heading,pitch,roll,LAT"}), "poses.csv:1: ",
               "header names column lat twice");
  expect_error(join({"# c", kHeader, "# no rows"}), "poses.csv:3: ",
               "no data row after the header: empty track");
}

TEST(CsvReader, RowErrors) {
  const auto row = [](const std::string& r) {
    return join({"# test", kHeader, "0,0,0,0,0,0,0", r, "1000,0,0,0,0,0,0"});
  };
  expect_error(row("1,0,0,0,0,0"), "poses.csv:4: ", "malformed row: 6 fields, the header has 7");
  expect_error(row("1,0,0,0,0,0,0,0"), "poses.csv:4: ", "malformed row: 8 fields");
  expect_error(row("1,0,x,0,0,0,0"), "poses.csv:4: ", "malformed lon 'x': expected a number");
  expect_error(row("1,0,0,,0,0,0"), "poses.csv:4: ", "malformed alt ''");
  expect_error(row("1,nan,0,0,0,0,0"), "poses.csv:4: ", "lat is not finite (nan)");
  expect_error(row("1,0,0,0,inf,0,0"), "poses.csv:4: ", "heading is not finite (inf)");
  expect_error(row("1,90.5,0,0,0,0,0"), "poses.csv:4: ", "lat 90.5 out of range [-90, 90]");
  expect_error(row("1,0,-360.01,0,0,0,0"), "poses.csv:4: ", "lon -360.01 out of range [-360, 360]");
  expect_error(row("1,0,0,250000,0,0,0"), "poses.csv:4: ", "alt 250000 out of range");
  expect_error(row("1,0,0,0,0,91,0"), "poses.csv:4: ", "pitch 91 out of range [-90, 90]");
  expect_error(row("yesterday,0,0,0,0,0,0"), "poses.csv:4: ",
               "malformed time 'yesterday': expected ISO 8601 UTC or seconds since the Unix epoch");
  expect_error(row("2024-05-01T12:00:00,0,0,0,0,0,0"), "poses.csv:4: ", "malformed time");
  expect_error(row("1e11,0,0,0,0,0,0"), "poses.csv:4: ", "time 1e+11 out of range");
  expect_error(row("\"1,0,0,0,0,0,0"), "poses.csv:4: ", "unterminated quoted field");
  expect_error(row("0,1,1,0,0,0,0"), "poses.csv:4: ",
               "time repeats: 0.000 s (1970-01-01T00:00:00Z) after 0.000 s");
  expect_error(row("-1,1,1,0,0,0,0"), "poses.csv:4: ", "time goes backwards");
  expect_error(
      join({kHeader, "2024-05-01T12:00:10Z,0,0,0,0,0,0", "2024-05-01T12:00:05Z,0,0,0,0,0,0"}),
      "poses.csv:3: ",
      "time goes backwards: 1714564805.000 s (2024-05-01T12:00:05Z) after "
      "1714564810.000 s (2024-05-01T12:00:10Z) (line 2)");
}

// Longitudes past +-180 (a track counted on across the antimeridian, or the 0..360
// convention) wrap into [-180, 180) once: |lon| up to 360. Latitudes do not wrap. A track
// across the antimeridian interpolates the short way, near +-180.
TEST(CsvReader, LongitudesPast180WrapLatitudesDoNot) {
  const std::string text = join({kHeader,
                                 "0,-17,179.998,3000,90,0,0",
                                 "1,-17,179.999,3000,90,0,0",
                                 "2,-17,180.001,3000,90,0,0",    // = -179.999
                                 "3,-17,-180.002,3000,90,0,0",   // = 179.998: turned back west
                                 "4,-17,359.5,3000,90,0,0",      // 0..360 convention: -0.5
                                 "5,-17,-360,3000,90,0,0"});     // = 0
  const PoseTrack t = parse_csv(text, "dateline.csv");
  ASSERT_EQ(t.samples.size(), 6u);
  const double expected[6] = {179.998, 179.999, -179.999, 179.998, -0.5, 0.0};
  for (std::size_t i = 0; i < 6; ++i) EXPECT_NEAR(t.samples[i].position.lon_deg, expected[i], 1e-9) << i;
  const double mid = t.at(1.5).position.lon_deg;
  EXPECT_NEAR(std::fabs(mid), 180.0, 1e-6);
  EXPECT_LT(mid, 180.0);
  PoseTrack crossing = t;
  crossing.samples.resize(3);
  for (const auto& p : cloudsvc::sim::replay_poses(crossing, 8.0, 0))
    EXPECT_GE(std::fabs(p.lon_deg), 179.998 - 1e-9) << "sim time " << p.sim_time_s << ": lon " << p.lon_deg;

  const auto row = [](const std::string& r) { return join({kHeader, "0,0,0,0,0,0,0", r}); };
  expect_error(row("1,0,360.5,0,0,0,0"), "poses.csv:3: ", "lon 360.5 out of range [-360, 360]");
  expect_error(row("1,-90.0001,0,0,0,0,0"), "poses.csv:3: ", "lat -90.0001 out of range [-90, 90]");
}

TEST(CsvReader, TruncatedLastRow) {
  expect_error(join({kHeader, "0,0,0,0,0,0,0", "1,0,0,0"}), "poses.csv:3: ",
               "truncated file: last row has 4 fields, the header has 7");
  expect_error(kHeader + "\n0,0,0,0,0,0,0\n1,0,0,0,0", "poses.csv:3: ", "truncated file");
}

}  // namespace
