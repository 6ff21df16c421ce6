// `cloudsvc serve --weather FILE.grib2` (service/forecast_tracker.h): the poses' frames show
// the forecast's clouds where it puts them, a client's layers replace the forecast, and a
// bad forecast file stops the service at start with one line. `sim_client weather --grib`
// streams a forecast to a running service with the same result, and a bad file leaves the
// service's weather as it was.
#include <gtest/gtest.h>

#include <fstream>

#include "cloudsvc_run.h"
#include "grib_test_support.h"
#include "service_test_support.h"
#include "shm_frame_stats.h"
#include "sim_client/service_connection.h"

namespace cloudsvc::test {
namespace {

using namespace std::chrono_literals;
using client::ServiceConnection;

constexpr double kT = 1780272000.0;  // 2026-06-01T00:00:00Z, s: the forecast's step

protocol::Pose looking_down(double lat, double lon, double utc_s) {
  protocol::Pose p;
  p.utc_unix_s = utc_s;
  p.lat_deg = lat;
  p.lon_deg = lon;
  p.alt_m = 4000.0;
  p.pitch_deg = -90.0;
  p.flags = protocol::pose_flag::kTeleport;
  return p;
}

FrameStats frame_of(ServiceConnection& c, const ServiceProcess& svc, const protocol::Pose& p) {
  c.send(p);
  const auto ready = c.receive_until<protocol::FrameReady>(120s);
  ShmFrame f;
  EXPECT_TRUE(read_frame(svc.shm_name(), ready.frame_number, f)) << "frame " << ready.frame_number;
  return stats_of(f);
}

// Low cloud cover 100 % over 0-30 E, 0-60 N (the regular_ll sample's area), 900-850 hPa.
std::filesystem::path low_cloud_forecast(const GribTempDir& dir) {
  const auto grib = dir.file("low.grib2");
  append_cloud_field(grib, 6, 1, 214, 100.0, 0);
  append_cloud_field(grib, 3, 0, 212, 90000.0, 0);
  append_cloud_field(grib, 3, 0, 213, 85000.0, 0);
  return grib;
}

TEST(ServiceForecast, FramesShowTheForecastsCloudsUntilAClientSendsLayers) {
  GribTempDir dir;
  const auto grib = low_cloud_forecast(dir);
  ServiceProcess svc("forecast", {"--weather", grib.string()});
  ASSERT_TRUE(svc.running());
  ServiceConnection c(svc.address(), "forecast");
  const FrameStats inside = frame_of(c, svc, looking_down(30.0, 15.0, kT));
  EXPECT_EQ(inside.nonfinite, 0u);
  EXPECT_GT(inside.cloud_fraction, 0.95);
  const FrameStats outside = frame_of(c, svc, looking_down(30.0, -40.0, kT));  // 4400 km west: new layers
  EXPECT_LT(outside.cloud_fraction, 0.02);
  const FrameStats back = frame_of(c, svc, looking_down(31.0, 16.0, kT + 3600.0));
  EXPECT_GT(back.cloud_fraction, 0.95);
  // A client's layers: overcast stratus everywhere, the forecast gone.
  protocol::WeatherLayers w;
  w.layers = {protocol::CloudLayer{10, 1000.0, 1500.0, 1.0, 1.0, 20.0, 0.0, 0.0}};
  c.send(w);
  EXPECT_GT(frame_of(c, svc, looking_down(30.0, -40.0, kT)).cloud_fraction, 0.95);
  EXPECT_EQ(svc.stop(), 0);
}

TEST(ServiceForecast, SimClientStreamsAForecastThatFramesShow) {
  GribTempDir dir;
  const auto grib = low_cloud_forecast(dir);
  // The service starts clear, its clock an hour before the forecast's step: the step's tiles
  // make a keyframe at its valid time.
  ServiceProcess svc("forecast_stream", {"--weather", "clear", "--time", "2026-05-31T23:00:00Z"});
  ASSERT_TRUE(svc.running());
  const RunResult r = run_sim_client({"weather", "--grib", grib.string(), "--at", "30,15", "--map-size", "360x180",
                                      "--quiet-ms", "200", "--connect", svc.address()},
                                     dir.file(""));
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("weather: sent the forecast " + grib.string() + ": 1 layer around 30,15 at "
                       "2026-06-01T00:00:00Z, 1 step from 2026-06-01T00:00:00Z as "),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("weather: accepted"), std::string::npos) << r.out;
  ServiceConnection c(svc.address(), "forecast");
  EXPECT_GT(frame_of(c, svc, looking_down(30.0, 15.0, kT)).cloud_fraction, 0.95);
  EXPECT_LT(frame_of(c, svc, looking_down(30.0, -40.0, kT)).cloud_fraction, 0.02);  // outside the forecast's cloud
  // A bad file: one line naming it, exit 2, and the service keeps the forecast's clouds.
  const auto text = dir.file("bad.grib2");
  std::ofstream(text) << "not a forecast\n";
  const RunResult bad = run_sim_client({"weather", "--grib", text.string(), "--at", "30,15", "--connect", svc.address()},
                                       dir.file(""));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err, "sim_client weather: --grib " + text.string() + ": not a GRIB file (no GRIB message found)\n");
  EXPECT_GT(frame_of(c, svc, looking_down(30.5, 15.5, kT)).cloud_fraction, 0.95);
  EXPECT_EQ(svc.stop(), 0);
}

TEST(ServiceForecast, ABadForecastFileStopsTheServiceAtStart) {
  GribTempDir dir;
  const auto text = dir.file("bad.grib2");
  std::ofstream(text) << "not a forecast\n";
  const RunResult r = run_cloudsvc({"serve", "--weather", text.string(), "--listen", "unix:" + dir.file("s.sock").string()},
                                   dir.file(""));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "cloudsvc serve: --weather " + text.string() + ": not a GRIB file (no GRIB message found)\n");
}

}  // namespace
}  // namespace cloudsvc::test
