// Tacview ACMI reader on synthetic recordings: header, reference point and time, T= forms
// with empty fields, escapes, continuations, object choice, removal, and every error with
// its file:line.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "geodesy/utc_time.h"
#include "sim_client/acmi_lexer.h"
#include "sim_client/acmi_reader.h"
#include "sim_client/flight_log_error.h"
#include "sim_client/replay_poses.h"

namespace {

using cloudsvc::geo::parse_utc_iso8601;
using cloudsvc::sim::AcmiOptions;
using cloudsvc::sim::FlightLogError;
using cloudsvc::sim::parse_acmi;
using cloudsvc::sim::PoseTrack;

const std::string kHeader = "FileType=text/acmi/tacview\nFileVersion=2.2\n";

std::string join(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& l : lines) text += l + "\n";
  return text;
}

AcmiOptions object(const std::string& o) {
  AcmiOptions options;
  options.object = o;
  return options;
}

double utc(const char* iso) { return parse_utc_iso8601(iso).value(); }

void expect_error(const std::string& text, const AcmiOptions& options, const std::string& prefix,
                  const std::string& fragment) {
  try {
    parse_acmi(text, "rec.acmi", options);
    ADD_FAILURE() << "no error; expected " << prefix << " ... " << fragment;
  } catch (const FlightLogError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

// A recording with one aircraft (id 3000102) and a ground object (id 1f), reference point
// 8 E 47 N.
const std::string kTwoObjects = "\xEF\xBB\xBF" + kHeader + join({
    "0,ReferenceTime=2011-06-02T05:00:00Z",  // line 3
    "0,ReferenceLongitude=8,ReferenceLatitude=47",
    "// a comment line",
    "1f,T=0.5|0.5|400,Type=Ground+Static+Building,Name=Tower",
    "#0.5",
    "3000102,T=0.1|0.2|1000|||,Name=C172,Type=Air+FixedWing",  // line 8
    "#1.5",
    "3000102,T=0.2||1100|5|2|90",
    "#2.5",
    "3000102,T=|0.3||||",
    "3000102,T=||1150|||-90",  // same frame: merged into the previous sample
    "#4",
    "3000102,T=0.3|0.3|1200|-10|3|370|1.5|2.5|123",  // 9 fields
    "-3000102",
    "#5",
    "3000102,T=0.4|0.4|1300",  // after removal: not followed
});

TEST(AcmiReader, FollowsAnObjectWithReferencePointAndEmptyFields) {
  const PoseTrack t = parse_acmi(kTwoObjects, "rec.acmi", object("3000102"));
  EXPECT_EQ(t.source, "rec.acmi object 3000102 (C172)");
  ASSERT_EQ(t.samples.size(), 4u);
  const double t0 = utc("2011-06-02T05:00:00Z");
  EXPECT_DOUBLE_EQ(t.samples[0].unix_time_s, t0 + 0.5);
  EXPECT_DOUBLE_EQ(t.samples[0].position.lon_deg, 8.1);
  EXPECT_DOUBLE_EQ(t.samples[0].position.lat_deg, 47.2);
  EXPECT_DOUBLE_EQ(t.samples[0].position.alt_m, 1000.0);
  // Empty lat kept, orientation set.
  EXPECT_DOUBLE_EQ(t.samples[1].unix_time_s, t0 + 1.5);
  EXPECT_DOUBLE_EQ(t.samples[1].position.lon_deg, 8.2);
  EXPECT_DOUBLE_EQ(t.samples[1].position.lat_deg, 47.2);
  EXPECT_DOUBLE_EQ(t.samples[1].position.alt_m, 1100.0);
  EXPECT_DOUBLE_EQ(t.samples[1].attitude.roll_deg, 5.0);
  EXPECT_DOUBLE_EQ(t.samples[1].attitude.pitch_deg, 2.0);
  EXPECT_DOUBLE_EQ(t.samples[1].attitude.heading_deg, 90.0);
  // Two updates in frame 2.5 merge; empty fields keep lon, roll, pitch; yaw -90 -> 270.
  EXPECT_DOUBLE_EQ(t.samples[2].unix_time_s, t0 + 2.5);
  EXPECT_DOUBLE_EQ(t.samples[2].position.lon_deg, 8.2);
  EXPECT_DOUBLE_EQ(t.samples[2].position.lat_deg, 47.3);
  EXPECT_DOUBLE_EQ(t.samples[2].position.alt_m, 1150.0);
  EXPECT_DOUBLE_EQ(t.samples[2].attitude.roll_deg, 5.0);
  EXPECT_DOUBLE_EQ(t.samples[2].attitude.heading_deg, 270.0);
  // 9-field form: Yaw is the heading (370 -> 10), U/V/Heading ignored.
  EXPECT_DOUBLE_EQ(t.samples[3].unix_time_s, t0 + 4.0);
  EXPECT_NEAR(t.samples[3].attitude.heading_deg, 10.0, 1e-12);
  EXPECT_DOUBLE_EQ(t.samples[3].attitude.roll_deg, -10.0);
  EXPECT_DOUBLE_EQ(t.samples[3].attitude.pitch_deg, 3.0);
  for (const auto& s : t.samples) EXPECT_TRUE(s.velocity_enu_mps.has_value());
}

// The first frame may lie before ReferenceTime: the header's records above it are at time 0
// without being a frame, so a negative first frame is not "backwards"; later frames are.
TEST(AcmiReader, AFirstFrameBeforeTheReferenceTime) {
  const std::string text = kHeader + join({"0,ReferenceTime=2020-01-01T00:00:00Z", "#-5", "7,T=8|47|1000,Name=X",
                                           "#-4.5", "7,T=8.1|47|1010"});
  const PoseTrack t = parse_acmi(text, "rec.acmi", object("7"));
  ASSERT_EQ(t.samples.size(), 2u);
  EXPECT_DOUBLE_EQ(t.samples[0].unix_time_s, utc("2020-01-01T00:00:00Z") - 5.0);
  EXPECT_DOUBLE_EQ(t.samples[1].unix_time_s, utc("2020-01-01T00:00:00Z") - 4.5);
  expect_error(kHeader + join({"0,ReferenceTime=2020-01-01T00:00:00Z", "#-5", "7,T=8|47|1000", "#-6"}), {},
               "rec.acmi:6: ", "time goes backwards: #-6 after #-5");
}

TEST(AcmiReader, FirstSampleWithoutOrientationGetsDerivedHeading) {
  // The 6-field T= of line 8 leaves Roll/Pitch/Yaw empty: orientation starts at 0 there,
  // given by the file from then on.
  const PoseTrack t = parse_acmi(kTwoObjects, "rec.acmi", object("c172"));
  EXPECT_DOUBLE_EQ(t.samples[0].attitude.heading_deg, 0.0);
  const std::string moving = kHeader + join({"0,ReferenceTime=2020-01-01T00:00:00Z",
                                             "#0", "7,T=10|0|1000", "#10", "7,T=10.01|0|1000",
                                             "#20", "7,T=10.02|0|1000"});
  const PoseTrack east = parse_acmi(moving, "m.acmi");
  ASSERT_EQ(east.samples.size(), 3u);
  for (const auto& s : east.samples) {
    EXPECT_NEAR(s.attitude.heading_deg, 90.0, 0.01);
    EXPECT_NEAR(s.velocity_enu_mps->x, 111.3, 0.1);  // 0.01 deg of equator per 10 s
  }
}

TEST(AcmiReader, ChoosesObjectsByIdOrName) {
  EXPECT_EQ(parse_acmi(kTwoObjects, "rec.acmi", object("0x1F")).source,
            "rec.acmi object 1f (Tower)");
  EXPECT_EQ(parse_acmi(kTwoObjects, "rec.acmi", object("tOWER")).source,
            "rec.acmi object 1f (Tower)");
  const PoseTrack tower = parse_acmi(kTwoObjects, "rec.acmi", object("1f"));
  ASSERT_EQ(tower.samples.size(), 1u);  // before the first frame: time 0
  EXPECT_DOUBLE_EQ(tower.samples[0].unix_time_s, utc("2011-06-02T05:00:00Z"));
  EXPECT_DOUBLE_EQ(tower.samples[0].position.lon_deg, 8.5);
  EXPECT_DOUBLE_EQ(tower.samples[0].position.lat_deg, 47.5);
  // An id that does not exist falls back to names: an object may be called "10".
  const std::string numeric_name =
      kHeader + join({"0,ReferenceTime=2020-01-01T00:00:00Z", "a,T=1|2|3,Name=10"});
  EXPECT_EQ(parse_acmi(numeric_name, "n.acmi", object("10")).source, "n.acmi object a (10)");
}

TEST(AcmiReader, EscapedCommasAndContinuations) {
  const std::string text = kHeader + join({
      "0,ReferenceTime=2020-01-01T00:00:00Z",
      "0,Comment=first line\\",  // line 4 continues on line 5
      "second line\\, still the comment",
      "5,Name=Smith\\, J.,T=1|2|3,Comment=a\\",
      "b",
      "#1",
      "5,T=1|2|4",  // line 9
      "5,T=1|2|4|nan|0|0",  // line 10: error, proves the line count survived continuations
  });
  expect_error(text, object("smith, j."), "rec.acmi:10: ", "roll is not finite");
  const std::string ok = text.substr(0, text.rfind("5,T=1|2|4|nan"));
  const PoseTrack t = parse_acmi(ok, "rec.acmi", object("SMITH, J."));
  EXPECT_EQ(t.source, "rec.acmi object 5 (Smith, J.)");
  ASSERT_EQ(t.samples.size(), 2u);
  EXPECT_DOUBLE_EQ(t.samples[1].position.alt_m, 4.0);

  // The lexer keeps a newline where the backslash was and unescapes "\,".
  std::vector<std::string> comments;
  cloudsvc::sim::acmi::lex_acmi(ok, "rec.acmi", [&](const cloudsvc::sim::acmi::Record& r) {
    for (const auto& p : r.properties)
      if (p.key == "Comment") comments.push_back(p.value);
  });
  ASSERT_EQ(comments.size(), 2u);
  EXPECT_EQ(comments[0], "first line\nsecond line, still the comment");
  EXPECT_EQ(comments[1], "a\nb");
}

TEST(AcmiReader, FileVersion21WithCrLfAndNoBom) {
  const std::string text =
      "FileType=text/acmi/tacview\r\nFileVersion=2.1\r\n0,ReferenceTime=2018-01-21T05:37:35Z\r\n"
      "#12.25\r\n1,T=1|2|3|4|5|6|7|8|9,Name=E-3A\r\n";
  const PoseTrack t = parse_acmi(text, "r.acmi");
  ASSERT_EQ(t.samples.size(), 1u);
  EXPECT_DOUBLE_EQ(t.samples[0].unix_time_s, utc("2018-01-21T05:37:35Z") + 12.25);
  EXPECT_DOUBLE_EQ(t.samples[0].attitude.heading_deg, 6.0);
}

TEST(AcmiReader, HeaderErrors) {
  expect_error("", {}, "rec.acmi:1: ", "missing ACMI header");
  expect_error(join({"FileVersion=2.2", "FileType=text/acmi/tacview"}), {}, "rec.acmi:1: ",
               "missing ACMI header: first line must be FileType=text/acmi/tacview");
  expect_error(join({"FileType=text/acmi/tacview"}), {}, "rec.acmi:1: ",
               "missing FileVersion");
  expect_error(join({"FileType=text/acmi/tacview", "0,ReferenceTime=2020-01-01T00:00:00Z"}), {},
               "rec.acmi:2: ", "missing FileVersion");
  expect_error(join({"FileType=text/acmi/tacview", "FileVersion=1.7"}), {}, "rec.acmi:2: ",
               "unsupported ACMI FileVersion '1.7'");
  expect_error(std::string("PK\x03\x04\x14\x00\x00\x00", 8) + "acmi.txt", {}, "rec.acmi:0: ",
               "unsupported: zipped ACMI (.zip.acmi); unzip first");
  // Reported at the first object record: the first place that needs an absolute time.
  expect_error(kHeader + join({"#0", "1,T=1|2|3"}), {}, "rec.acmi:4: ",
               "missing global 0,ReferenceTime");
  expect_error(kHeader, {}, "rec.acmi:1: ", "missing global 0,ReferenceTime");
  expect_error(kHeader + join({"0,ReferenceTime=2020-13-01T00:00:00Z", "1,T=1|2|3"}), {},
               "rec.acmi:3: ", "ReferenceTime '2020-13-01T00:00:00Z' is not an ISO 8601");
  expect_error(kHeader + join({"0,ReferenceTime=2020-01-01T00:00:00Z", "0,ReferenceLatitude=x"}),
               {}, "rec.acmi:4: ", "malformed ReferenceLatitude 'x'");
}

TEST(AcmiReader, RecordErrors) {
  const std::string head = kHeader + "0,ReferenceTime=2020-01-01T00:00:00Z\n";  // 3 lines
  expect_error(head + join({"#1", "#0.5"}), {}, "rec.acmi:5: ",
               "time goes backwards: #0.5 after #1");
  expect_error(head + join({"#abc"}), {}, "rec.acmi:4: ", "malformed time frame");
  expect_error(head + join({"#inf"}), {}, "rec.acmi:4: ", "time frame is not finite");
  expect_error(head + join({"1,T=1|2|3", "xyz,T=1|2|3"}), {}, "rec.acmi:5: ",
               "malformed record 'xyz,T=1|2|3'");
  expect_error(head + join({"1,T=1|2|3,Color"}), {}, "rec.acmi:4: ",
               "malformed property 'Color': expected Key=Value");
  expect_error(head + join({"-zz"}), {}, "rec.acmi:4: ", "malformed object removal");
  expect_error(head + join({"1,T=1|2|3|4"}), {}, "rec.acmi:4: ",
               "4 fields, expected 3, 5, 6 or 9");
  expect_error(head + join({"1,T=1|2|3|4|5|6|7"}), {}, "rec.acmi:4: ", "7 fields");
  expect_error(head + join({"1,T=1|2|abc"}), {}, "rec.acmi:4: ", "malformed T= altitude 'abc'");
  expect_error(head + join({"1,T=1|2|3|-inf|0|0"}), {}, "rec.acmi:4: ",
               "roll is not finite (-inf)");
  // Another object's malformed T= fails too: the file is broken.
  expect_error(head + join({"1,T=1|2|3", "2,T=1|2"}), object("1"), "rec.acmi:5: ",
               "2 fields");
  expect_error(head + "1,Name=x\\", {}, "rec.acmi:4: ",
               "truncated file: line continuation");
}

TEST(AcmiReader, RangeErrorsOfTheChosenObject) {
  const std::string head =
      kHeader + "0,ReferenceTime=2020-01-01T00:00:00Z\n0,ReferenceLatitude=80\n";  // 4 lines
  expect_error(head + join({"1,T=0|5|0", "#1", "1,T=0|10.5|0"}), {}, "rec.acmi:7: ",
               "latitude 90.5 out of range [-90, 90]");
  // Longitudes wrap (LongitudesWrapAcrossTheAntimeridian); only a non-finite sum is an error.
  EXPECT_DOUBLE_EQ(parse_acmi(head + join({"1,T=181|5|0"}), "rec.acmi").samples[0].position.lon_deg, -179.0);
  expect_error(kHeader + join({"0,ReferenceTime=2020-01-01T00:00:00Z", "0,ReferenceLongitude=1e308",
                               "1,T=1e308|5|0"}),
               {}, "rec.acmi:5: ", "longitude is not finite (inf)");
  expect_error(head + join({"1,T=1|5|300000"}), {}, "rec.acmi:5: ",
               "altitude 300000 out of range");
  expect_error(head + join({"1,T=1|5|10|0|95|0"}), {}, "rec.acmi:5: ",
               "pitch 95 out of range [-90, 90]");
  expect_error(head + join({"1,T=|5|10"}), {}, "rec.acmi:5: ",
               "first T= of object 1 leaves longitude, latitude or altitude empty");
  // Another object out of range does not matter.
  EXPECT_NO_THROW(parse_acmi(head + join({"1,T=1|5|10", "2,T=1|50|10"}), "rec.acmi", object("1")));
}

// A frame time is any finite number of seconds after ReferenceTime, but the sample it makes
// must lie in years 1900-2199 like every log's: said at the frame's T= line. It had been read,
// and the replay then refused "pose at : Pose.utc_unix_s 1e+300 out of range" (no line, no
// time: the year was beyond what the formatter writes).
TEST(AcmiReader, FrameTimesBeyondTheYearsOfALogNameTheLine) {
  const std::string head = kHeader + "0,ReferenceTime=2026-06-21T12:00:00Z\n";  // 3 lines
  expect_error(head + join({"#0", "1,T=8|47|2000", "#1e300", "1,T=8.001|47|2000"}), {}, "rec.acmi:7: ",
               "frame time #1e+300 after ReferenceTime '2026-06-21T12:00:00Z' is out of range: sample times must be "
               "in years 1900-2199");
  expect_error(head + join({"#0", "1,T=8|47|2000", "#1e10", "1,T=8.001|47|2000"}), {}, "rec.acmi:7: ", "#1e+10");
  expect_error(kHeader + join({"0,ReferenceTime=2199-12-31T23:59:00Z", "#0", "1,T=8|47|2000", "#60",
                               "1,T=8.001|47|2000"}),
               {}, "rec.acmi:7: ", "#60 after ReferenceTime '2199-12-31T23:59:00Z' is out of range");  // 2200-01-01
  // Up to the last second of 2199 is a time a pose may have.
  const PoseTrack t = parse_acmi(kHeader + join({"0,ReferenceTime=2199-12-31T23:59:00Z", "#0", "1,T=8|47|2000", "#59.5",
                                                 "1,T=8.001|47|2000"}),
                                 "rec.acmi");
  ASSERT_EQ(t.samples.size(), 2u);
  EXPECT_DOUBLE_EQ(t.samples[1].unix_time_s, utc("2199-12-31T23:59:59.5Z"));
}

// Tacview positions are ReferenceLongitude + offset: a flight across the antimeridian runs
// past 180 and wraps into [-180, 180); the track, its derived heading and speed, the
// interpolated poses and the replay poses all stay on the short way across. Latitudes do
// not wrap.
TEST(AcmiReader, LongitudesWrapAcrossTheAntimeridian) {
  const std::string text = kHeader + join({
      "0,ReferenceTime=2020-01-01T00:00:00Z",
      "0,ReferenceLongitude=180,ReferenceLatitude=-17",
      "#0", "7,T=-0.0015|0.2|3000",  // 179.9985
      "#1", "7,T=-0.0005|0.2|3000",  // 179.9995
      "#2", "7,T=0.0005|0.2|3000",   // 180.0005 = -179.9995
      "#3", "7,T=0.0015|0.2|3000",   // 180.0015 = -179.9985
  });
  const PoseTrack t = parse_acmi(text, "dateline.acmi");
  ASSERT_EQ(t.samples.size(), 4u);
  const double expected[4] = {179.9985, 179.9995, -179.9995, -179.9985};
  for (std::size_t i = 0; i < 4; ++i) {
    SCOPED_TRACE(i);
    EXPECT_NEAR(t.samples[i].position.lon_deg, expected[i], 1e-9);
    EXPECT_NEAR(t.samples[i].position.lat_deg, -16.8, 1e-9);
    EXPECT_NEAR(t.samples[i].attitude.heading_deg, 90.0, 0.1) << "flying east";
    EXPECT_NEAR(t.samples[i].velocity_enu_mps->x, 106.5, 1.0) << "0.001 deg of longitude per s at 16.8 S";
  }
  const double t0 = t.start_time();
  const double mid = t.at(t0 + 1.5).position.lon_deg;  // between 179.9995 and -179.9995
  EXPECT_NEAR(std::fabs(mid), 180.0, 1e-6);
  EXPECT_GE(mid, -180.0);
  EXPECT_LT(mid, 180.0);
  const std::vector<cloudsvc::protocol::Pose> poses = cloudsvc::sim::replay_poses(t, 10.0, 0);
  ASSERT_EQ(poses.size(), 31u);
  for (const auto& p : poses) {
    EXPECT_GE(std::fabs(p.lon_deg), 179.9985 - 1e-9) << "sim time " << p.sim_time_s << ": lon " << p.lon_deg;
    EXPECT_LT(p.lon_deg, 180.0);
  }

  // Any finite sum wraps; the reference alone may be anywhere.
  const std::string far = kHeader + join({"0,ReferenceTime=2020-01-01T00:00:00Z", "0,ReferenceLongitude=-180",
                                          "#0", "7,T=-0.5|0|100", "#1", "7,T=530|0|100"});
  const PoseTrack f = parse_acmi(far, "far.acmi");
  ASSERT_EQ(f.samples.size(), 2u);
  EXPECT_NEAR(f.samples[0].position.lon_deg, 179.5, 1e-9);
  EXPECT_NEAR(f.samples[1].position.lon_deg, -10.0, 1e-9);

  // Latitudes: reference + offset past a pole is an error naming the sum.
  const std::string head = kHeader + "0,ReferenceTime=2020-01-01T00:00:00Z\n0,ReferenceLatitude=-89.9995\n";
  expect_error(head + join({"1,T=0|-0.001|0"}), {}, "rec.acmi:5: ", "latitude -90.0005 out of range [-90, 90]");
}

TEST(AcmiReader, ObjectChoiceErrors) {
  const std::string head = kHeader + "0,ReferenceTime=2020-01-01T00:00:00Z\n";
  const std::string two = head + join({"1,T=1|2|3,Name=Hornet", "2,T=1|2|3,Name=hornet",
                                       "3,Name=NoPosition"});
  expect_error(two, {}, "rec.acmi:0: ",
               "2 objects have positions; choose one by hex id or Name: 1 (Hornet), 2 (hornet)");
  expect_error(two, object("HORNET"), "rec.acmi:0: ",
               "object name 'HORNET' is ambiguous: objects 1, 2 have it");
  expect_error(two, object("Viper"), "rec.acmi:0: ",
               "unknown object 'Viper': no object has that hex id or Name; objects with "
               "positions: 1 (Hornet), 2 (hornet)");
  expect_error(two, object("3"), "rec.acmi:0: ",
               "object 3 (NoPosition) has no position (T=): empty track");
  expect_error(two, object("nOpOsition"), "rec.acmi:0: ", "has no position");
  expect_error(head, {}, "rec.acmi:0: ", "no object with a position (T=): empty track");
  expect_error(head + join({"-9", "#1", "9,T=1|2|3"}), {}, "rec.acmi:0: ",
               "object 9 has no position before its removal: empty track");
}

}  // namespace
