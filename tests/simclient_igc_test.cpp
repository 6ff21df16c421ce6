// IGC reader on synthetic logs: date forms, B-record decoding, midnight wrap, duplicates,
// I-record extensions, altitude fallback, and every error with its file:line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "geodesy/utc_time.h"
#include "sim_client/flight_log_error.h"
#include "sim_client/igc_reader.h"
#include "sim_client/replay_poses.h"

namespace {

using cloudsvc::geo::parse_utc_iso8601;
using cloudsvc::sim::FlightLogError;
using cloudsvc::sim::IgcOptions;
using cloudsvc::sim::parse_igc;
using cloudsvc::sim::PoseTrack;

// B record from its fields (no checks: malformed records are built the same way).
std::string b(const std::string& hhmmss, const std::string& lat = "4700000N",
              const std::string& lon = "00800000E", const std::string& validity = "A",
              const std::string& pressure = "01000", const std::string& gnss = "01050",
              const std::string& extensions = "") {
  return "B" + hhmmss + lat + lon + validity + pressure + gnss + extensions;
}

std::string join(const std::vector<std::string>& lines, const char* eol = "\n") {
  std::string text;
  for (const std::string& l : lines) text += l + eol;
  return text;
}

double utc(const char* iso) { return parse_utc_iso8601(iso).value(); }

// The parse fails with what() starting "<prefix>" and containing `fragment`, on one line.
void expect_error(const std::string& text, const std::string& prefix, const std::string& fragment,
                  const IgcOptions& options = {}) {
  try {
    parse_igc(text, "flight.igc", options);
    ADD_FAILURE() << "no error; expected " << prefix << " ... " << fragment;
  } catch (const FlightLogError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(IgcReader, DecodesFixesWithTheShortDateForm) {
  const std::string text = join(
      {"AXXXABC FLIGHT:1", "HFDTE160701", "HFPLTPILOTINCHARGE: Bloggs",
       b("120000", "4730500N", "00830250W", "A", "00500", "00612"),
       b("120004", "4730600S", "17959999E", "A", "-0012", "-0005"),
       b("120008", "0000000N", "00000000E", "A", "00000", "00007"), "LXXX comment",
       "GREJNGJERJKNJKRE31895478537H43982FJN9248F942389T433T"},
      "\r\n");
  const PoseTrack t = parse_igc(text, "flight.igc");
  EXPECT_EQ(t.source, "flight.igc");
  ASSERT_EQ(t.samples.size(), 3u);
  EXPECT_DOUBLE_EQ(t.samples[0].unix_time_s, utc("2001-07-16T12:00:00Z"));
  EXPECT_NEAR(t.samples[0].position.lat_deg, 47.0 + 30.5 / 60.0, 1e-12);
  EXPECT_NEAR(t.samples[0].position.lon_deg, -(8.0 + 30.25 / 60.0), 1e-12);
  EXPECT_DOUBLE_EQ(t.samples[0].position.alt_m, 612.0);  // GNSS altitude
  EXPECT_NEAR(t.samples[1].position.lat_deg, -(47.0 + 30.6 / 60.0), 1e-12);
  EXPECT_NEAR(t.samples[1].position.lon_deg, 179.0 + 59.999 / 60.0, 1e-12);
  EXPECT_DOUBLE_EQ(t.samples[1].position.alt_m, -5.0);  // negative GNSS altitude
  EXPECT_DOUBLE_EQ(t.samples[2].unix_time_s, utc("2001-07-16T12:00:08Z"));
  EXPECT_DOUBLE_EQ(t.samples[2].position.lat_deg, 0.0);  // a valid (A) fix at 0 N 0 E stays
}

TEST(IgcReader, LongDateFormAndExtensionsAreIgnoredSafely) {
  // I record declares LAD/LOD after byte 35; a second, nonsense I record must not matter.
  const std::string text =
      join({"AXCTb9d15853a7c25f72", "HFDTEDATE:070422,01", "I023636LAD3737LOD", "Igarbage",
            b("113450", "4538365N", "01256696E", "A", "00000", "00120", "67"),
            b("113451", "4538366N", "01256696E", "A", "00000", "00121", "68XYZ and more"),
            "J010812HDT"});
  const PoseTrack t = parse_igc(text, "x.igc");
  ASSERT_EQ(t.samples.size(), 2u);
  EXPECT_DOUBLE_EQ(t.samples[0].unix_time_s, utc("2022-04-07T11:34:50Z"));
  EXPECT_NEAR(t.samples[0].position.lat_deg, 45.0 + 38.365 / 60.0, 1e-12);
  EXPECT_NEAR(t.samples[1].position.lon_deg, 12.0 + 56.696 / 60.0, 1e-12);
  EXPECT_DOUBLE_EQ(t.samples[1].position.alt_m, 121.0);
}

TEST(IgcReader, OtherDateRecordSpellings) {
  for (const char* date : {"HFDTE:311299", "HODTE311299", "HFDTEDATE:311299"}) {
    const PoseTrack t = parse_igc(join({"AXXX", date, b("235959")}), "d.igc");
    EXPECT_DOUBLE_EQ(t.samples[0].unix_time_s, utc("1999-12-31T23:59:59Z")) << date;
  }
  const PoseTrack y2k = parse_igc(join({"AXXX", "HFDTE290200", b("000000")}), "d.igc");
  EXPECT_DOUBLE_EQ(y2k.samples[0].unix_time_s, utc("2000-02-29T00:00:00Z"));
}

TEST(IgcReader, MidnightWrapContinuesOnTheNextDay) {
  const std::string text =
      join({"AXXX", "HFDTE061109", b("235958", "3839773S", "17608501E"),
            b("235959", "3839774S", "17608501E"), b("000001", "3839775S", "17608501E"),
            b("000002", "3839776S", "17608501E"), b("013000", "3839777S", "17608501E")});
  const PoseTrack t = parse_igc(text, "nz.igc");
  ASSERT_EQ(t.samples.size(), 5u);
  EXPECT_DOUBLE_EQ(t.samples[0].unix_time_s, utc("2009-11-06T23:59:58Z"));
  EXPECT_DOUBLE_EQ(t.samples[2].unix_time_s, utc("2009-11-07T00:00:01Z"));
  EXPECT_DOUBLE_EQ(t.samples[4].unix_time_s, utc("2009-11-07T01:30:00Z"));
  for (std::size_t i = 1; i < t.samples.size(); ++i)
    EXPECT_GT(t.samples[i].unix_time_s, t.samples[i - 1].unix_time_s);
}

TEST(IgcReader, SkipsDuplicateTimestamps) {
  const std::string text =
      join({"AXXX", "HFDTE010120", b("100000"), b("100001", "4700010N"),
            b("100001", "4700020N"), b("100001", "4700030N"), b("100002", "4700040N")});
  const PoseTrack t = parse_igc(text, "dup.igc");
  ASSERT_EQ(t.samples.size(), 3u);
  EXPECT_NEAR(t.samples[1].position.lat_deg, 47.0 + 0.01 / 60.0, 1e-12);  // first one kept
  EXPECT_DOUBLE_EQ(t.samples[2].unix_time_s, utc("2020-01-01T10:00:02Z"));
}

TEST(IgcReader, PressureAltitudeFallbackWithMedianOffset) {
  // GNSS - pressure = 50, 50, 47 on the good fixes: median offset 50.
  const std::string text = join({"AXXX", "HFDTE010120",
                                 b("100000", "4700000N", "00800000E", "A", "01000", "01050"),
                                 b("100001", "4700001N", "00800000E", "A", "01010", "01060"),
                                 b("100002", "4700002N", "00800000E", "A", "01020", "00000"),
                                 b("100003", "4700003N", "00800000E", "V", "01030", "01500"),
                                 b("100004", "4700004N", "00800000E", "A", "01040", "01087"),
                                 b("100005", "0000000N", "00000000E", "V", "01050", "00000"),
                                 b("100006", "4700006N", "00800000E", "A", "01060", "01110")});
  const PoseTrack t = parse_igc(text, "alt.igc");
  ASSERT_EQ(t.samples.size(), 6u);  // the V fix at 0 N 0 E (no position) is dropped
  EXPECT_DOUBLE_EQ(t.samples[2].position.alt_m, 1070.0);  // GNSS 0 -> 1020 + 50
  EXPECT_DOUBLE_EQ(t.samples[3].position.alt_m, 1080.0);  // V fix -> 1030 + 50
  EXPECT_DOUBLE_EQ(t.samples[4].position.alt_m, 1087.0);
  EXPECT_DOUBLE_EQ(t.samples[5].unix_time_s, utc("2020-01-01T10:00:06Z"));
}

TEST(IgcReader, DerivesAttitudeFromTheTrack) {
  // Due east at 47 N: 0.050 min of longitude (63.4 m) every 2 s = 31.7 m/s, climbing
  // 2 m every 2 s.
  std::vector<std::string> lines = {"AXXX", "HFDTE010120"};
  for (int k = 0; k < 10; ++k) {
    char lon[16], hhmmss[8], gnss[8];
    std::snprintf(lon, sizeof lon, "008%05dE", 50 * k);
    std::snprintf(hhmmss, sizeof hhmmss, "1000%02d", 2 * k);
    std::snprintf(gnss, sizeof gnss, "%05d", 1000 + 2 * k);
    lines.push_back(b(hhmmss, "4700000N", lon, "A", "00900", gnss));
  }
  const PoseTrack t = parse_igc(join(lines), "east.igc");
  ASSERT_EQ(t.samples.size(), 10u);
  for (const auto& s : t.samples) {
    EXPECT_NEAR(s.attitude.heading_deg, 90.0, 0.1);
    EXPECT_NEAR(s.attitude.roll_deg, 0.0, 0.01);
    EXPECT_NEAR(s.attitude.pitch_deg, std::atan(1.0 / 31.6) * 180.0 / std::numbers::pi, 0.1);
    ASSERT_TRUE(s.velocity_enu_mps.has_value());
    EXPECT_NEAR(s.velocity_enu_mps->x, 31.6, 0.3);
  }
}

TEST(IgcReader, TimeGoingBackwards) {
  const std::string text = join({"AXXX", "HFDTE010120", b("120000"), b("120010", "4700010N"),
                                 b("120005", "4700020N"), b("120020", "4700030N")});
  expect_error(text, "flight.igc:5: ", "time goes backwards: 2020-01-01T12:00:05Z after "
                                       "2020-01-01T12:00:10Z (line 4)");
  IgcOptions skip;
  skip.skip_out_of_order = true;
  const PoseTrack t = parse_igc(text, "flight.igc", skip);
  ASSERT_EQ(t.samples.size(), 3u);
  EXPECT_DOUBLE_EQ(t.samples[2].unix_time_s, utc("2020-01-01T12:00:20Z"));
  // A decrease of exactly 12 h is not a midnight wrap.
  expect_error(join({"AXXX", "HFDTE010120", b("180000"), b("060000")}), "flight.igc:4: ",
               "time goes backwards");
}

TEST(IgcReader, HeaderAndDateErrors) {
  expect_error(join({"HFDTE010120", b("120000")}), "flight.igc:1: ", "missing A record");
  expect_error(join({"", "  ", "Bxyz"}), "flight.igc:3: ", "missing A record");
  expect_error("", "flight.igc:0: ", "empty file");
  expect_error(join({"AXXX", "HFPLTPILOT:x", b("120000")}), "flight.igc:3: ",
               "missing date");
  expect_error(join({"AXXX", b("120000"), "HFDTE010120"}), "flight.igc:2: ", "missing date");
  expect_error(join({"AXXX", "HFDTE01012", b("120000")}), "flight.igc:2: ",
               "malformed date record");
  expect_error(join({"AXXX", "HFDTEDATE:0A0120,01", b("120000")}), "flight.igc:2: ",
               "malformed date record");
  expect_error(join({"AXXX", "HFDTE300222", b("120000")}), "flight.igc:2: ", "invalid date");
  expect_error(join({"AXXX", "HFDTE011322", b("120000")}), "flight.igc:2: ", "invalid date");
}

TEST(IgcReader, MalformedAndOutOfRangeFixes) {
  const auto with = [](const std::string& rec) {
    return join({"AXXX", "HFDTE010120", b("115959"), rec, b("120100")});
  };
  expect_error(with(b("12a000")), "flight.igc:4: ", "time '12a000' is not HHMMSS");
  expect_error(with(b("250000")), "flight.igc:4: ", "time 250000 out of range");
  expect_error(with(b("120060")), "flight.igc:4: ", "out of range");
  expect_error(with(b("120000", "9100000N")), "flight.igc:4: ",
               "latitude 91 deg out of range [-90, 90]");
  expect_error(with(b("120000", "4760000N")), "flight.igc:4: ", "latitude minutes 60");
  expect_error(with(b("120000", "4700000X")), "flight.igc:4: ", "malformed B record: latitude");
  expect_error(with(b("120000", "4700000N", "18100000E")), "flight.igc:4: ",
               "longitude 181 deg out of range [-180, 180]");
  expect_error(with(b("120000", "4700000N", "0080 000E")), "flight.igc:4: ",
               "malformed B record: longitude");
  expect_error(with(b("120000", "4700000N", "00800000E", "X")), "flight.igc:4: ",
               "fix validity 'X' is not A or V");
  expect_error(with(b("120000", "4700000N", "00800000E", "A", "0x100")), "flight.igc:4: ",
               "pressure altitude");
  expect_error(with(b("120000", "4700000N", "00800000E", "A", "01000", "01-00")),
               "flight.igc:4: ", "GNSS altitude");
  expect_error(with("B1200004700000N00800000EA01000"), "flight.igc:4: ",
               "malformed B record: 30 characters, a fix needs at least 35");
}

// The longitude field's degrees are 000-180: a fix written as 180 degrees and some minutes
// (a recorder counting on past the antimeridian) is the same point as 179 degrees and 60
// minus those minutes on the other side and wraps there; 181 or more is an error. A flight
// across the antimeridian keeps its heading, and interpolated poses stay near +-180.
TEST(IgcReader, LongitudesJustPast180WrapAcrossTheAntimeridian) {
  const std::string text = join({"AXXX", "HFDTE010120",
                                 b("120000", "1700000S", "17959880E"),    // 179.998
                                 b("120001", "1700000S", "17959940E"),    // 179.999
                                 b("120002", "1700000S", "18000060E"),    // 180.001 = -179.999
                                 b("120003", "1700000S", "18000000W"),    // -180 (= 180)
                                 b("120004", "1700000S", "17959880W")});  // -179.998
  const PoseTrack t = parse_igc(text, "dateline.igc");
  ASSERT_EQ(t.samples.size(), 5u);
  const double expected[5] = {179.998, 179.999, -179.999, -180.0, -179.998};
  for (std::size_t i = 0; i < 5; ++i) {
    SCOPED_TRACE(i);
    EXPECT_NEAR(t.samples[i].position.lon_deg, expected[i], 1e-9);
    EXPECT_GE(t.samples[i].position.lon_deg, -180.0);
    EXPECT_LT(t.samples[i].position.lon_deg, 180.0);
  }
  // 180.001 -> -180 goes back west by 0.001 degrees: the heading says so, the others east.
  EXPECT_NEAR(t.samples[0].attitude.heading_deg, 90.0, 0.1);
  const double mid = t.at(t.start_time() + 1.5).position.lon_deg;  // between 179.999 and -179.999
  EXPECT_NEAR(std::fabs(mid), 180.0, 1e-6);
  EXPECT_LT(mid, 180.0);
  for (const auto& p : cloudsvc::sim::replay_poses(t, 4.0, 0))
    EXPECT_GE(std::fabs(p.lon_deg), 179.998 - 1e-9) << "sim time " << p.sim_time_s << ": lon " << p.lon_deg;

  const auto with = [](const std::string& rec) { return join({"AXXX", "HFDTE010120", b("115959"), rec}); };
  expect_error(with(b("120000", "1700000S", "18100000W")), "flight.igc:4: ",
               "longitude 181 deg out of range [-180, 180]");
  expect_error(with(b("120000", "9000060N", "17959880W")), "flight.igc:4: ",
               "latitude 90.001 deg out of range [-90, 90]");
}

TEST(IgcReader, TruncatedFileAndEmptyTrack) {
  expect_error(join({"AXXX", "HFDTE010120", b("120000"), "B1200014700000N00800000EA010"}),
               "flight.igc:4: ", "truncated file");
  // Cut without a final newline, as a partial download would be.
  expect_error("AXXX\r\nHFDTE010120\r\n" + b("120000") + "\r\nB12000147000", "flight.igc:4: ",
               "truncated file");
  expect_error(join({"AXXX", "HFDTE010120", "LXXX no fixes", ""}), "flight.igc:4: ",
               "empty track");
}

}  // namespace
