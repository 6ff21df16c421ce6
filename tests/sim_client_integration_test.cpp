// The sim_client executable against a real `cloudsvc serve` (child process, Unix socket,
// 64x36 frames so that llvmpipe renders in a few tens of milliseconds): replay, sweep,
// weather (preset and map), watch, and the exit codes of bad input and connection
// failures.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <OpenImageIO/imagebuf.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "service_test_support.h"
#include "shm_test_ring.h"
#include "sim_client/service_connection.h"

namespace cloudsvc::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

std::string read_file(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

// Runs build/bin/sim_client with `args` (no shell quoting needed: the tests' paths have no
// spaces), stdout and stderr captured into files of `dir`.
RunResult run_sim_client(const fs::path& dir, const std::string& args) {
  static int counter = 0;
  const std::string tag = std::to_string(++counter);
  const fs::path out = dir / ("out" + tag + ".txt"), err = dir / ("err" + tag + ".txt");
  const std::string cmd = std::string(CLOUDSVC_BIN_DIR) + "/sim_client " + args + " > " + out.string() + " 2> " + err.string();
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

// A 5-row CSV flight log, one row per second.
fs::path write_log(const fs::path& dir) {
  const fs::path csv = dir / "flight.csv";
  std::ofstream f(csv);
  f << "time,lat,lon,alt,heading,pitch,roll\n";
  for (int i = 0; i < 5; ++i)
    f << "2026-06-21T12:00:0" << i << "Z," << 47.45 + 0.0005 * i << ",8.56," << 1500 + 50 * i << ",90,3,0\n";
  return csv;
}

TEST(SimClientCli, ReplayOfAFivePoseCsvWritesFiveFramesAndASummary) {
  ServiceProcess svc("simcli_replay", {}, ServiceProcess::Tcp::No, ServiceProcess::OutDir::Yes);
  ASSERT_TRUE(svc.running());
  const fs::path log = write_log(svc.dir());
  const fs::path frames = svc.out_dir() / "frames" / "nested";  // created by sim_client
  const fs::path sheet = svc.dir() / "sheet.png";
  const RunResult r = run_sim_client(svc.dir(), "replay " + log.string() + " --connect " + svc.address() + " --out " +
                                                    frames.string() + " --size 64x36 --fps 1 --contact-sheet " +
                                                    sheet.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::size_t pngs = 0;
  for (const auto& e : fs::directory_iterator(frames)) pngs += e.path().extension() == ".png";
  EXPECT_EQ(pngs, 5u);
  EXPECT_NE(r.out.find("replay: 5 frames, 5 poses sent, "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("latency mean "), std::string::npos);
  EXPECT_NE(r.out.find("render mean "), std::string::npos);
  // stderr is not a terminal here: progress lines, no carriage returns.
  EXPECT_NE(r.err.find("replay: 100% (5/5 frames"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos);
  // 5 frames: 3 columns x 2 rows of 64x36 tiles with 4 px gaps.
  OIIO::ImageBuf img(sheet.string());
  ASSERT_TRUE(img.read());
  EXPECT_EQ(img.spec().width, 3 * 64 + 4 * 4);
  EXPECT_EQ(img.spec().height, 2 * 36 + 3 * 4);
  EXPECT_EQ(svc.stop(), 0);
}

TEST(SimClientCli, RealtimeReplayReportsFramesAgainstPoses) {
  ServiceProcess svc("simcli_realtime");
  ASSERT_TRUE(svc.running());
  const fs::path log = write_log(svc.dir());
  const RunResult r = run_sim_client(svc.dir(), "replay " + log.string() + " --connect " + svc.address() +
                                                    " --size 64x36 --fps 5 --realtime");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(" poses sent, "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("21 poses sent"), std::string::npos) << r.out;  // 4 s at 5 Hz, both ends
  EXPECT_NE(r.out.find("superseded before rendering (latest wins)"), std::string::npos) << r.out;
  EXPECT_EQ(svc.stop(), 0);
}

TEST(SimClientCli, SweepOfThreePosesWritesAManifestWithFiniteStatistics) {
  ServiceProcess svc("simcli_sweep", {}, ServiceProcess::Tcp::No, ServiceProcess::OutDir::Yes);
  ASSERT_TRUE(svc.running());
  const fs::path sweep = svc.dir() / "sweep.json";
  std::ofstream(sweep) << R"({"time": "2026-06-21T12:00:00Z", "poses": [
      {"lat": 47.45, "lon": 8.56, "alt": 2500, "heading": 270, "pitch": 5, "weather": "clear"},
      {"lat": 47.45, "lon": 8.56, "alt": 2500, "heading": 270, "pitch": 5, "weather": "overcast-stratus"},
      {"lat": 47.45, "lon": 8.56, "alt": 600, "heading": 90, "pitch": 10}]})";
  const fs::path out = svc.out_dir() / "sweep";
  const RunResult r = run_sim_client(svc.dir(), "sweep " + sweep.string() + " --connect " + svc.address() + " --out " +
                                                    out.string() + " --size 64x36 --png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("sweep: 3 of 3 entries rendered"), std::string::npos) << r.out;
  double fps = -1.0, median_ms = -1.0, p95_ms = -1.0;
  const auto at = r.out.find(" s, ");
  ASSERT_NE(at, std::string::npos) << r.out;
  ASSERT_EQ(std::sscanf(r.out.c_str() + at, " s, %lf frames/s, latency median %lf ms p95 %lf ms, manifest ", &fps,
                        &median_ms, &p95_ms), 3) << r.out;
  EXPECT_GT(fps, 0.0);
  EXPECT_GT(median_ms, 0.0);
  EXPECT_LE(median_ms, p95_ms);
  const auto rows = lines_of(read_file(out / "manifest.csv"));
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0],
            "frame,lat,lon,alt,heading,pitch,roll,utc,weather,render_ms,latency_ms,mean_radiance,cloud_fraction,"
            "nonfinite,file");
  std::vector<double> fractions;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::vector<std::string> f;
    std::stringstream in(rows[i]);
    for (std::string cell; std::getline(in, cell, ',');) f.push_back(cell);
    ASSERT_EQ(f.size(), 15u) << rows[i];
    EXPECT_EQ(f[7], "2026-06-21T12:00:00.000Z");
    const double mean_radiance = std::stod(f[11]), cloud_fraction = std::stod(f[12]);
    EXPECT_TRUE(std::isfinite(mean_radiance) && mean_radiance > 0.0) << rows[i];
    EXPECT_TRUE(cloud_fraction >= 0.0 && cloud_fraction <= 1.0) << rows[i];
    EXPECT_EQ(f[13], "0") << "NaN/Inf pixels in " << rows[i];
    EXPECT_TRUE(fs::exists(f[14])) << f[14];
    EXPECT_EQ(fs::path(f[14]).extension(), ".exr");
    EXPECT_TRUE(fs::exists(fs::path(f[14]).replace_extension(".png")));
    fractions.push_back(cloud_fraction);
  }
  EXPECT_EQ(rows[1].find(",clear,") != std::string::npos, true) << rows[1];
  EXPECT_NE(rows[2].find(",overcast-stratus,"), std::string::npos) << rows[2];
  EXPECT_NE(rows[3].find(",overcast-stratus,"), std::string::npos) << "the weather stays until changed";
  EXPECT_EQ(fractions[0], 0.0) << "a clear sky has no cloud pixels";
  EXPECT_GT(fractions[2], 0.5) << "inside the stratus deck (400-900 m) most pixels are cloud";
  EXPECT_EQ(svc.stop(), 0);
}

TEST(SimClientCli, WeatherPresetAndMapAreAcceptedAndFramesStillRender) {
  ServiceProcess svc("simcli_weather");
  ASSERT_TRUE(svc.running());
  const RunResult preset = run_sim_client(svc.dir(), "weather --preset stratocumulus-deck --quiet-ms 200 --connect " + svc.address());
  ASSERT_EQ(preset.exit_code, 0) << preset.err;
  EXPECT_NE(preset.out.find("weather: accepted (no error from the service)"), std::string::npos) << preset.out;
  EXPECT_EQ(preset.err, "");

  // A 2-channel float map (coverage, density) larger than one tile in width.
  const fs::path map = svc.dir() / "map.exr";
  {
    const int w = 1500, h = 40;
    std::vector<float> px(static_cast<std::size_t>(w) * h * 2);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        px[(static_cast<std::size_t>(y) * w + x) * 2 + 0] = static_cast<float>(x) / (w - 1);
        px[(static_cast<std::size_t>(y) * w + x) * 2 + 1] = 0.5f;
      }
    OIIO::ImageBuf buf(OIIO::ImageSpec(w, h, 2, OIIO::TypeDesc::FLOAT));
    ASSERT_TRUE(buf.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, px.data()));
    ASSERT_TRUE(buf.write(map.string()));
  }
  const RunResult tiles = run_sim_client(
      svc.dir(), "weather --map " + map.string() +
                     " --bounds 45,5,50,12 --valid-at 2026-06-21T12:05:00Z --channels coverage,density --quiet-ms 200 "
                     "--connect " + svc.address());
  ASSERT_EQ(tiles.exit_code, 0) << tiles.err;
  EXPECT_NE(tiles.out.find("as 2 tiles (1500x40 texels, channels coverage,density"), std::string::npos) << tiles.out;
  EXPECT_NE(tiles.out.find("weather: accepted"), std::string::npos);

  // The service still renders.
  client::ServiceConnection c(svc.address(), "weather-check");
  protocol::Pose p;
  p.sim_time_s = 1.0;
  p.lat_deg = 47.45;
  p.lon_deg = 8.56;
  p.alt_m = 2500.0;
  p.heading_deg = 270.0;
  c.send(p);
  const auto ready = c.receive_until<protocol::FrameReady>(60s);
  EXPECT_EQ(ready.pose.lat_deg, 47.45);
  EXPECT_EQ(svc.stop(), 0);
}

TEST(SimClientCli, WatchCountsFramesForOneSecond) {
  ServiceProcess svc("simcli_watch");
  ASSERT_TRUE(svc.running());
  client::ServiceConnection c(svc.address(), "watch-driver");
  int sent = 0;
  auto render_one = [&] {
    protocol::Pose p;
    p.sim_time_s = ++sent;
    p.lat_deg = 47.45;
    p.lon_deg = 8.56;
    p.alt_m = 2000.0;
    p.heading_deg = sent;
    c.send(p);
    c.receive_until<protocol::FrameReady>(60s);
  };
  render_one();  // the first frame of a service also builds its weather volumes: slow
  RunResult watch;
  std::atomic<bool> watching{true};
  std::thread watcher([&] {
    watch = run_sim_client(svc.dir(), "watch --shm " + svc.shm_name() + " --seconds 1");
    watching = false;
  });
  // Frames while it watches: one pose at a time until the watcher has finished, however
  // long it takes to start on a loaded machine.
  const int before = sent;
  while (watching) render_one();
  watcher.join();
  ASSERT_EQ(watch.exit_code, 0) << watch.err;
  const auto lines = lines_of(watch.out);
  ASSERT_GE(lines.size(), 2u) << watch.out;
  EXPECT_EQ(lines[0].rfind("t ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(" frames/s, newest #"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("64x36 RGBA16F linear"), std::string::npos) << lines[0];
  unsigned long long frames = 0;
  ASSERT_EQ(std::sscanf(lines.back().c_str(), "watch: %llu frames in", &frames), 1) << lines.back();
  EXPECT_GE(frames, 1u);
  EXPECT_LE(frames, static_cast<unsigned long long>(sent - before));
  // Latency = watcher's clock at first sight - the slot's publish time: the watcher polls
  // every millisecond, so it is far below a frame time, and never negative.
  const auto at = lines.back().find(", latency mean ");
  ASSERT_NE(at, std::string::npos) << lines.back();
  double mean_ms = -1.0, max_ms = -1.0;
  ASSERT_EQ(std::sscanf(lines.back().c_str() + at, ", latency mean %lf ms max %lf ms", &mean_ms, &max_ms), 2) << lines.back();
  EXPECT_GE(mean_ms, 0.0);
  EXPECT_LE(mean_ms, max_ms);
  EXPECT_LT(max_ms, 500.0);
  EXPECT_EQ(svc.stop(), 0);
}

// A ring whose header claims 2 slots of 2^63 bytes: 2^63 x 2 wraps to 0 in 64 bits, so an
// unchecked reader takes the ring for 8 KiB and, at the first new frame, reads slot 1 far
// outside the mapping. While `watch` runs, this test publishes frames into the ring as a
// service would; `watch` must refuse the ring with one line naming the fields (exit 1),
// not die of SIGSEGV.
TEST(SimClientCli, WatchRefusesARingWhoseSlotSizesWrapAround) {
  const fs::path dir = fs::temp_directory_path() / ("simcli_hostile_ring_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  cloudsvc_shm_header h{};
  h.magic = CLOUDSVC_SHM_MAGIC;
  h.version = CLOUDSVC_SHM_VERSION;
  h.header_bytes = CLOUDSVC_SHM_HEADER_BYTES;
  h.slot_count = 2;
  h.slot_stride = std::uint64_t{1} << 63;
  h.max_width = 16;
  h.max_height = 16;
  h.latest_frame = 1;
  h.latest_slot = 1;
  TestRing ring("watch-wrap", h, 2 * CLOUDSVC_SHM_HEADER_BYTES);
  std::atomic<bool> done{false};
  RunResult r;
  std::thread watcher([&] {
    r = run_sim_client(dir, "watch --shm " + ring.name() + " --seconds 1");
    done = true;
  });
  std::atomic_ref<std::uint64_t> latest(ring.header()->latest_frame);
  while (!done) {  // a new frame every 5 ms until the watcher has exited, however it exits
    latest.fetch_add(1);
    std::this_thread::sleep_for(5ms);
  }
  watcher.join();
  EXPECT_EQ(r.exit_code, 1) << "stdout: " << r.out << " stderr: " << r.err;
  EXPECT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("sim_client watch: --shm " + ring.name() + ": ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("slot_stride"), std::string::npos) << r.err;
  std::error_code ec;
  fs::remove_all(dir, ec);
}

TEST(SimClientCli, BadInputExitsTwoAndConnectionFailureExitsOneWithOneLine) {
  const fs::path dir = fs::temp_directory_path() / ("simcli_bad_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path log = write_log(dir);

  RunResult r = run_sim_client(dir, "replay " + log.string() + " --fps abc");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "sim_client replay: --fps abc: expected a finite number in (0, 1000] (frames per second of log time)\n");

  r = run_sim_client(dir, "sweep x.json --bogus");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines_of(r.err).size(), 1u);
  EXPECT_NE(r.err.find("--bogus"), std::string::npos) << r.err;

  const fs::path bad_log = dir / "bad.csv";
  std::ofstream(bad_log) << "time,lat,lon,alt,heading,pitch,roll\n2026-06-21T12:00:00Z,47,8,1500,90,0,0\n"
                            "2026-06-21T12:00:01Z,95,8,1500,90,0,0\n";
  r = run_sim_client(dir, "replay " + bad_log.string() + " --connect unix:" + (dir / "none.sock").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind(bad_log.string() + ":3: ", 0), 0u) << r.err;
  EXPECT_EQ(lines_of(r.err).size(), 1u);

  r = run_sim_client(dir, "replay " + log.string() + " --connect unix:" + (dir / "none.sock").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("sim_client replay: unix:", 0), 0u) << r.err;

  r = run_sim_client(dir, "watch --shm cloudsvc-absent-ring-" + std::to_string(::getpid()) + " --seconds 1");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(lines_of(r.err).size(), 1u) << r.err;

  r = run_sim_client(dir, "weather --map " + (dir / "absent.exr").string() + " --bounds 40,0,50,20");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "sim_client weather: --valid-at \"\": required with --map: the UTC time the map is valid at\n");

  // Forecasts: each mistake is one line naming the flag, before any connection is tried.
  const std::string none = " --connect unix:" + (dir / "none.sock").string();
  r = run_sim_client(dir, "weather --grib gfs.grib2" + none);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "sim_client weather: --at \"\": required with --grib or --metar: LAT,LON[,TIME], where the layers are made\n");
  r = run_sim_client(dir, "weather --grib reports.metar --at 47,8" + none);
  EXPECT_EQ(r.err, "sim_client weather: --grib reports.metar: expected a GRIB2 file (.grib2, .grb2, .grib, .grb)\n");
  r = run_sim_client(dir, "weather --metar reports.metar --preset clear --at 47,8" + none);
  EXPECT_EQ(r.err, "sim_client weather: --preset clear: not with a forecast (--grib, --metar): it sends its own layers and map\n");
  r = run_sim_client(dir, "weather --metar reports.metar --at 47,8,noon" + none);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("sim_client weather: --at noon: expected a UTC ISO 8601 time", 0), 0u) << r.err;
  const fs::path metar = dir / "reports.metar";
  std::ofstream(metar) << "METAR LSZH 211150Z 24008KT 9999 FEW030 BKN3O0 18/09 Q1017\n";
  r = run_sim_client(dir, "weather --metar " + metar.string() + " --at 47,8,2026-06-21T12:00Z" + none);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("sim_client weather: --metar " + metar.string() + ": line 1: malformed sky group 'BKN3O0'", 0), 0u)
      << r.err;
  r = run_sim_client(dir, "weather --preset clear --at 47,8" + none);
  EXPECT_EQ(r.err, "sim_client weather: --at 47,8: only with --grib or --metar\n");

  r = run_sim_client(dir, "--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* cmd : {"replay", "sweep", "weather", "watch"}) EXPECT_NE(r.out.find(cmd), std::string::npos);
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
}  // namespace cloudsvc::test
