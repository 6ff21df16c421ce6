// load_flight_log on the real logs in ../shared/data/flightlogs (read in place, never
// copied) and on small files written to a temporary directory (extension dispatch, I/O
// errors).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "geodesy/utc_time.h"
#include "sim_client/angles.h"
#include "sim_client/flight_log.h"

namespace {

namespace fs = std::filesystem;
using cloudsvc::geo::parse_utc_iso8601;
using cloudsvc::sim::FlightLogError;
using cloudsvc::sim::load_flight_log;
using cloudsvc::sim::LogOptions;
using cloudsvc::sim::PoseTrack;
using cloudsvc::sim::wrap_deg_180;

double utc(const char* iso) { return parse_utc_iso8601(iso).value(); }

// Path of a shared log, or "" (the caller skips) when the data directory is absent.
std::string shared_log(const char* name) {
  const fs::path p = fs::path(CLOUDSVC_SHARED_DATA_DIR) / "flightlogs" / name;
  return fs::exists(p) ? p.string() : std::string();
}

#define REQUIRE_SHARED_LOG(var, name)                                                  \
  const std::string var = shared_log(name);                                            \
  if (var.empty())                                                                     \
    GTEST_SKIP() << "shared flight log " << name << " not found under "                \
                 << CLOUDSVC_SHARED_DATA_DIR "/flightlogs (public test data, see "     \
                    "../shared/data/README.md)";

std::vector<std::string> b_records(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);)
    if (!l.empty() && l[0] == 'B') out.push_back(l);
  return out;
}

std::string error_of(const std::string& path, const LogOptions& options = {}) {
  try {
    load_flight_log(path, options);
  } catch (const FlightLogError& e) {
    return e.what();
  }
  return "(no error)";
}

void expect_sane(const PoseTrack& t) {
  for (std::size_t i = 0; i < t.samples.size(); ++i) {
    const auto& s = t.samples[i];
    if (i > 0) {
      ASSERT_GT(s.unix_time_s, t.samples[i - 1].unix_time_s) << i;
    }
    ASSERT_GE(s.attitude.heading_deg, 0.0) << i;
    ASSERT_LT(s.attitude.heading_deg, 360.0) << i;
    ASSERT_LE(std::fabs(s.attitude.roll_deg), 75.0) << i;
    ASSERT_LE(std::fabs(s.attitude.pitch_deg), 45.0) << i;
  }
}

// --- IGC ---------------------------------------------------------------------------------

TEST(RealLogs, AerofilesExampleHasAFixOutOfOrder) {
  REQUIRE_SHARED_LOG(path, "aerofiles-example.igc");
  // The specification's example file: ... 16:03:10, 22:02:48, 16:02:52, 16:02:52.
  const std::string err = error_of(path);
  EXPECT_EQ(err, path + ":48: time goes backwards: 2001-07-16T16:02:52Z after "
                        "2001-07-16T22:02:48Z (line 47)");
  LogOptions skip;
  skip.skip_out_of_order = true;
  const PoseTrack t = load_flight_log(path, skip);
  EXPECT_EQ(t.source, path);
  ASSERT_EQ(t.samples.size(), 8u);  // 10 B records, the two at 16:02:52 dropped
  EXPECT_DOUBLE_EQ(t.start_time(), utc("2001-07-16T16:02:40Z"));
  EXPECT_DOUBLE_EQ(t.end_time(), utc("2001-07-16T22:02:48Z"));
  // B1602405407121N00249342WA0028000421...
  EXPECT_NEAR(t.samples[0].position.lat_deg, 54.0 + 7.121 / 60.0, 1e-12);
  EXPECT_NEAR(t.samples[0].position.lon_deg, -(2.0 + 49.342 / 60.0), 1e-12);
  EXPECT_DOUBLE_EQ(t.samples[0].position.alt_m, 421.0);
  expect_sane(t);
}

TEST(RealLogs, XcTrackParaglider) {
  REQUIRE_SHARED_LOG(path, "aerofiles-xctrack-2022-04-07.igc");
  const PoseTrack t = load_flight_log(path);
  ASSERT_EQ(t.samples.size(), 294u);  // one fix a second, no repeats
  ASSERT_EQ(b_records(path).size(), 294u);
  EXPECT_DOUBLE_EQ(t.start_time(), utc("2022-04-07T11:34:50Z"));
  EXPECT_DOUBLE_EQ(t.end_time(), utc("2022-04-07T11:39:43Z"));
  // B1134504538365N01256696EA0000000000067 (LAD/LOD extension bytes ignored).
  EXPECT_NEAR(t.samples[0].position.lat_deg, 45.0 + 38.365 / 60.0, 1e-12);
  EXPECT_NEAR(t.samples[0].position.lon_deg, 12.0 + 56.696 / 60.0, 1e-12);
  EXPECT_DOUBLE_EQ(t.samples[0].position.alt_m, 0.0);  // GNSS 0, no baro (pressure 0)
  double max_speed = 0.0, max_alt = 0.0;
  for (const auto& s : t.samples) {
    max_speed = std::max(max_speed, std::hypot(s.velocity_enu_mps->x, s.velocity_enu_mps->y));
    max_alt = std::max(max_alt, s.position.alt_m);
    EXPECT_NEAR(s.position.lat_deg, 45.64, 0.01);
    EXPECT_NEAR(s.position.lon_deg, 12.945, 0.01);
  }
  EXPECT_GT(max_speed, 8.0);   // a paraglider flies 8-15 m/s over ground
  EXPECT_LT(max_speed, 25.0);
  EXPECT_GT(max_alt, 100.0);   // climbed above 100 m
  expect_sane(t);
}

TEST(RealLogs, NewZealandGliderAcrossMidnight) {
  REQUIRE_SHARED_LOG(path, "igclib-new_zealand.igc");
  const PoseTrack t = load_flight_log(path);
  const std::vector<std::string> b = b_records(path);
  ASSERT_EQ(t.samples.size(), 5367u);
  ASSERT_EQ(b.size(), t.samples.size());
  EXPECT_DOUBLE_EQ(t.start_time(), utc("2009-11-06T23:48:08Z"));
  EXPECT_DOUBLE_EQ(t.end_time(), utc("2009-11-07T04:08:30Z"));  // past midnight UTC
  // B2348083839773S17608501EA0035200458...
  EXPECT_NEAR(t.samples[0].position.lat_deg, -(38.0 + 39.773 / 60.0), 1e-12);
  EXPECT_NEAR(t.samples[0].position.lon_deg, 176.0 + 8.501 / 60.0, 1e-12);
  EXPECT_DOUBLE_EQ(t.samples[0].position.alt_m, 458.0);
  for (const auto& s : t.samples) {  // southern hemisphere near 176 E
    ASSERT_LT(s.position.lat_deg, -38.0);
    ASSERT_GT(s.position.lat_deg, -39.0);
    ASSERT_GT(s.position.lon_deg, 175.5);
    ASSERT_LT(s.position.lon_deg, 177.0);
  }
  expect_sane(t);

  // The recorder logs its own true track (TRT, bytes 55-57) and ground speed (GSP, bytes
  // 47-51, 1/100 km/h) in I-record extensions that the reader ignores: the derived heading
  // and speed must agree with them while flying (GSP > 43 km/h).
  std::vector<double> heading_err, speed_err;
  std::size_t banked = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double gsp = std::stoi(b[i].substr(46, 5)) / 100.0 / 3.6;
    const double trt = std::stoi(b[i].substr(54, 3));
    if (gsp < 12.0) continue;
    const auto& s = t.samples[i];
    heading_err.push_back(std::fabs(wrap_deg_180(s.attitude.heading_deg - trt)));
    speed_err.push_back(
        std::fabs(std::hypot(s.velocity_enu_mps->x, s.velocity_enu_mps->y) / gsp - 1.0));
    if (std::fabs(s.attitude.roll_deg) > 25.0) ++banked;
  }
  ASSERT_GT(heading_err.size(), 5000u);
  const auto quantile = [](std::vector<double> v, double q) {
    const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + k, v.end());
    return v[static_cast<std::size_t>(k)];
  };
  EXPECT_LT(quantile(heading_err, 0.5), 2.0);   // measured 0.8 deg
  EXPECT_LT(quantile(heading_err, 0.9), 6.0);   // measured 3.1 deg
  EXPECT_LT(quantile(speed_err, 0.5), 0.03);    // measured 1.2 %
  EXPECT_LT(quantile(speed_err, 0.9), 0.12);    // measured 6.5 %
  // A cross-country glider flight is about one third thermalling at 30-50 deg of bank.
  const double banked_fraction = static_cast<double>(banked) / heading_err.size();
  EXPECT_GT(banked_fraction, 0.2);
  EXPECT_LT(banked_fraction, 0.6);
}

// --- ACMI --------------------------------------------------------------------------------

TEST(RealLogs, PyacmiSample) {
  REQUIRE_SHARED_LOG(path, "pyacmi-test.acmi");
  {
    std::ifstream in(path, std::ios::binary);
    char bom[3] = {};
    in.read(bom, 3);
    ASSERT_EQ(std::string(bom, 3), "\xEF\xBB\xBF") << "the sample should start with a BOM";
  }
  const double ref = utc("2018-01-21T05:37:35Z");
  // Five objects with positions, two of them named E-3A.
  EXPECT_EQ(error_of(path), path + ":0: 5 objects have positions; choose one by hex id or "
                                   "Name: 1 (E-3A), 2 (E-3A), 3, 4, 5");
  LogOptions by_name;
  by_name.acmi_object = "e-3a";
  EXPECT_EQ(error_of(path, by_name),
            path +
                ":0: object name 'e-3a' is ambiguous: objects 1, 2 have it; choose one by hex id");

  // Object 1: 9-field T=1|2|3|4|5|6|7|8|9 at #0.54, reference 40 E 42 N added.
  LogOptions one;
  one.acmi_object = "1";
  const PoseTrack t1 = load_flight_log(path, one);
  EXPECT_EQ(t1.source, path + " object 1 (E-3A)");
  ASSERT_EQ(t1.samples.size(), 1u);
  EXPECT_DOUBLE_EQ(t1.samples[0].unix_time_s, ref + 0.54);
  EXPECT_DOUBLE_EQ(t1.samples[0].position.lon_deg, 41.0);
  EXPECT_DOUBLE_EQ(t1.samples[0].position.lat_deg, 44.0);
  EXPECT_DOUBLE_EQ(t1.samples[0].position.alt_m, 3.0);
  EXPECT_DOUBLE_EQ(t1.samples[0].attitude.roll_deg, 4.0);
  EXPECT_DOUBLE_EQ(t1.samples[0].attitude.pitch_deg, 5.0);
  EXPECT_DOUBLE_EQ(t1.samples[0].attitude.heading_deg, 6.0);

  // Object 3: 5-field T=1|2|3|4|5 before the first frame (time 0 = ReferenceTime).
  LogOptions three;
  three.acmi_object = "3";
  const PoseTrack t3 = load_flight_log(path, three);
  ASSERT_EQ(t3.samples.size(), 1u);
  EXPECT_DOUBLE_EQ(t3.samples[0].unix_time_s, ref);
  EXPECT_DOUBLE_EQ(t3.samples[0].position.lon_deg, 41.0);
  EXPECT_DOUBLE_EQ(t3.samples[0].position.lat_deg, 44.0);
  EXPECT_DOUBLE_EQ(t3.samples[0].position.alt_m, 3.0);  // U|V = 4|5 ignored

  // Object 4: 3-field T=1|2|3.
  LogOptions four;
  four.acmi_object = "4";
  const PoseTrack t4 = load_flight_log(path, four);
  ASSERT_EQ(t4.samples.size(), 1u);
  EXPECT_DOUBLE_EQ(t4.samples[0].position.lat_deg, 44.0);
}

// --- extension dispatch and file errors --------------------------------------------------

class TempDir : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cloudsvc_simclient_logs_" + std::to_string(::getpid()) + "_" +
            testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& content) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }
  fs::path dir_;
};

using FlightLogFiles = TempDir;

TEST_F(FlightLogFiles, DispatchesOnTheExtension) {
  const std::string csv = "time,lat,lon,alt,heading,pitch,roll\n0,1,2,3,4,5,6\n1,1,2,3,4,5,6\n";
  EXPECT_EQ(load_flight_log(write("a.csv", csv)).samples.size(), 2u);
  EXPECT_EQ(load_flight_log(write("B.CSV", csv)).samples.size(), 2u);
  const std::string igc = "AXXX\nHFDTE010120\nB1200004700000N00800000EA0100001050\n";
  EXPECT_EQ(load_flight_log(write("c.igc", igc)).samples.size(), 1u);
  EXPECT_EQ(load_flight_log(write("d.IGC", igc)).samples.size(), 1u);
  const std::string acmi =
      "FileType=text/acmi/tacview\nFileVersion=2.2\n0,ReferenceTime=2020-01-01T00:00:00Z\n"
      "1,T=1|2|3\n";
  EXPECT_EQ(load_flight_log(write("e.acmi", acmi)).samples.size(), 1u);
  EXPECT_EQ(load_flight_log(write("f.txt.acmi", acmi)).samples.size(), 1u);
  // The extension decides: CSV content in an .igc file is not an IGC log.
  const std::string wrong = write("g.igc", csv);
  EXPECT_EQ(error_of(wrong), wrong + ":1: missing A record: an IGC file starts with the A "
                                     "(manufacturer) record, found 'time,lat,lon,alt,heading,"
                                     "pitch,roll'");
}

TEST_F(FlightLogFiles, FileLevelErrors) {
  const std::string zip = write("h.zip.acmi", std::string("PK\x03\x04", 4));
  EXPECT_EQ(error_of(zip), zip + ":0: unsupported: zipped ACMI (.zip.acmi); unzip first");
  // A zipped file named plain .acmi is recognised by its signature.
  const std::string zip2 = write("i.acmi", std::string("PK\x03\x04rest", 8));
  EXPECT_EQ(error_of(zip2), zip2 + ":0: unsupported: zipped ACMI (.zip.acmi); unzip first");
  const std::string gpx = write("j.gpx", "<gpx/>");
  EXPECT_EQ(error_of(gpx),
            gpx + ":0: unsupported file type: expected .igc, .acmi, .txt.acmi or .csv");
  const std::string missing = (dir_ / "none.igc").string();
  EXPECT_EQ(error_of(missing), missing + ":0: cannot open: No such file or directory");
  fs::create_directories(dir_ / "l.igc");
  const std::string directory = (dir_ / "l.igc").string();
  EXPECT_EQ(error_of(directory), directory + ":0: cannot open: is a directory");
  const std::string empty = write("k.csv", "");
  EXPECT_EQ(error_of(empty), empty + ":0: missing header row time,lat,lon,alt,heading,pitch,roll");
}

}  // namespace
