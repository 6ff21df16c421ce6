// The parts of `sim_client soak` that need no service: the clients' track,
// VmRSS from /proc, and the report (key=value lines, JSON, failure verdict) of a
// run laid out by hand.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "geodesy/geodetic.h"
#include "protocol/validate.h"
#include "sim_client/process_rss.h"
#include "sim_client/soak_client.h"
#include "sim_client/soak_summary.h"
#include "sim_client/soak_track.h"

namespace cloudsvc::sim {
namespace {

double ecef_distance_m(const protocol::Pose& a, const protocol::Pose& b) {
  const glm::dvec3 pa = geo::geodetic_to_ecef({a.lat_deg, a.lon_deg, a.alt_m});
  const glm::dvec3 pb = geo::geodetic_to_ecef({b.lat_deg, b.lon_deg, b.alt_m});
  return glm::length(pb - pa);
}

TEST(SoakTrack, EveryClientFliesAValidSmoothCoordinatedTurn) {
  const SoakTrack track;
  EXPECT_NEAR(track.radius_m(), 70.0 / (3.0 * M_PI / 180.0), 1e-9);
  for (std::size_t client = 0; client < 10; ++client) {
    SCOPED_TRACE(client);
    protocol::Pose previous = track.pose(client, 0.0);
    for (int k = 1; k <= 200; ++k) {  // 20 s at 10 Hz
      const double t = 0.1 * k;
      const protocol::Pose p = track.pose(client, t);
      ASSERT_FALSE(protocol::validate(protocol::Message(p))) << *protocol::validate(protocol::Message(p));
      EXPECT_DOUBLE_EQ(p.sim_time_s, t);
      // 70 m/s: 7 m per 0.1 s (the chord of a 0.3 deg arc is shorter by 1e-6).
      EXPECT_NEAR(ecef_distance_m(previous, p), 7.0, 0.01);
      // 3 deg/s to the right.
      double turn = p.heading_deg - previous.heading_deg;
      if (turn < -180.0) turn += 360.0;
      EXPECT_NEAR(turn, 0.3, 1e-9);
      EXPECT_NEAR(p.roll_deg, 20.5, 0.1);  // atan(70 * 0.05236 / 9.80665)
      ASSERT_TRUE(p.velocity_enu.has_value());
      EXPECT_NEAR(std::hypot(p.velocity_enu->east_mps, p.velocity_enu->north_mps), 70.0, 1e-9);
      // The velocity points along the heading.
      EXPECT_NEAR(std::atan2(p.velocity_enu->east_mps, p.velocity_enu->north_mps) * 180.0 / M_PI,
                  p.heading_deg > 180.0 ? p.heading_deg - 360.0 : p.heading_deg, 1e-9);
      previous = p;
    }
  }
  // No two of the most clients (1024) send the same pose at the same sim time: the
  // FrameReady echo says whose it was.
  std::vector<protocol::Pose> at_1s;
  for (std::size_t c = 0; c < 1024; ++c) at_1s.push_back(track.pose(c, 1.0));
  std::size_t same = 0;
  for (std::size_t a = 0; a < at_1s.size(); ++a)
    for (std::size_t b = a + 1; b < at_1s.size(); ++b)
      same += at_1s[a].lat_deg == at_1s[b].lat_deg && at_1s[a].lon_deg == at_1s[b].lon_deg &&
              at_1s[a].alt_m == at_1s[b].alt_m;
  EXPECT_EQ(same, 0u);
}

// The pose schedule: k / rate after the start, never past the end. `--rate 1e-300
// --duration 1s` (a valid rate: one pose in the run) had made pose 1 due 1e300 s after the
// start, beyond the clock's int64 nanoseconds: the cast wrapped to a time long past, every
// pose was due at once and the client flooded the service and never stopped.
TEST(SoakSchedule, PosesAreDueAtKOverRateAndNeverPastTheEnd) {
  using namespace std::chrono_literals;
  const auto start = std::chrono::steady_clock::time_point{} + 1000s;
  const auto end = start + 1s;
  EXPECT_EQ(soak_pose_due(start, end, 0, 60.0), start);
  EXPECT_EQ(soak_pose_due(start, end, 30, 60.0), start + 500ms);
  EXPECT_EQ(soak_pose_due(start, end, 60, 60.0), end);   // due at the end: not sent
  EXPECT_EQ(soak_pose_due(start, end, 61, 60.0), end);
  EXPECT_EQ(soak_pose_due(start, end, 0, 1e-300), start);
  EXPECT_EQ(soak_pose_due(start, end, 1, 1e-300), end);  // 1e300 s: past the end, not a wrapped time
  EXPECT_EQ(soak_pose_due(start, end, 1, 4.9e-324), end);  // 1 / denormal = inf
  EXPECT_EQ(soak_pose_due(start, end, UINT64_MAX, 10000.0), end);
  const auto week = start + std::chrono::hours(24 * 7);  // the longest --duration
  EXPECT_EQ(soak_pose_due(start, week, 604799, 1.0), start + 604799s);
}

TEST(SoakRss, VmRssOfAStatusTextAndOfLiveAndGoneProcesses) {
  EXPECT_EQ(vmrss_bytes_of_status("Name:\tcloudsvc\nVmPeak:\t  900 kB\nVmRSS:\t  123456 kB\nThreads:\t4\n"),
            123456u * 1024u);
  EXPECT_FALSE(vmrss_bytes_of_status("Name:\tkthreadd\nThreads:\t1\n"));  // kernel threads and zombies have none
  EXPECT_FALSE(vmrss_bytes_of_status("VmRSS:\t  12x kB\n"));
  const std::optional<std::uint64_t> self = process_rss_bytes(::getpid());
  ASSERT_TRUE(self.has_value());
  EXPECT_GT(*self, 1024u * 1024u) << "a gtest process holds more than 1 MiB";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) _exit(0);
  ASSERT_EQ(::waitpid(child, nullptr, 0), child);  // reaped: the pid names no process now
  EXPECT_FALSE(process_rss_bytes(child).has_value());
  EXPECT_FALSE(process_rss_bytes(0).has_value());

  RssRange r;
  for (std::uint64_t v : {300u, 500u, 400u}) r.add(v);
  EXPECT_EQ(r.start, 300u);
  EXPECT_EQ(r.max, 500u);
  EXPECT_EQ(r.end, 400u);
  EXPECT_EQ(r.samples, 3u);
}

// Two clients as a run would leave them: client 0 got frames 10..13, its own 11 and 13;
// client 1 got 10..12 and an Overloaded error.
SoakSummary two_clients() {
  SoakSummary s;
  s.addresses = {"unix:/tmp/a.sock"};
  s.rate_hz = 100.0;
  s.duration_s = 2.0;
  s.run_s = 2.0;
  s.width = 160;
  s.height = 90;
  s.view_sent = true;
  s.threads = 2;
  SoakClientStats a;
  a.address = "unix:/tmp/a.sock";
  a.poses_sent = 200;
  a.frames = 4;
  a.own_frames = 2;
  a.frame_numbers = {10, 11, 12, 13};
  a.latency_ms = {20.0, 40.0};
  a.service_latency_ms = {15.0, 30.0};
  a.final_stats = true;
  SoakClientStats b = a;
  b.poses_sent = 199;
  b.frames = 3;
  b.own_frames = 1;
  b.frame_numbers = {10, 11, 12};
  b.latency_ms = {100.0};
  b.service_latency_ms = {90.0};
  b.errors["Overloaded"] = 2;
  s.clients = {a, b};
  protocol::Stats start, end;
  start.frames_rendered = 9;
  start.poses_received = 1;
  end.frames_rendered = 13;
  end.poses_received = 400;
  end.poses_dropped = 395;
  s.service_start = start;
  s.service_end = end;
  s.service_pid = 4242;
  s.rss.add(100u * 1024 * 1024);
  s.rss.add(120u * 1024 * 1024);
  s.rss.add(110u * 1024 * 1024);
  return s;
}

std::map<std::string, std::string> key_values(const std::string& report) {
  std::map<std::string, std::string> kv;
  std::istringstream in(report);
  std::string line;
  std::getline(in, line);  // the readable first line
  while (std::getline(in, line)) {
    const auto eq = line.find('=');
    EXPECT_NE(eq, std::string::npos) << line;
    if (eq != std::string::npos) kv[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return kv;
}

TEST(SoakReport, TotalsPerClientFiguresAndVerdict) {
  const SoakSummary s = two_clients();
  const std::string text = format_soak_report(s, false);
  EXPECT_EQ(text.rfind("soak: 2 clients x 100 Hz for 2 s (unix:/tmp/a.sock), view 160x90\n", 0), 0u) << text;
  const auto kv = key_values(text);
  EXPECT_EQ(kv.at("clients"), "2");
  EXPECT_EQ(kv.at("poses_sent"), "399");
  EXPECT_EQ(kv.at("frames_received"), "7");
  EXPECT_EQ(kv.at("frames_distinct"), "4");
  EXPECT_EQ(kv.at("frame_rate_hz"), "2.000");  // 4 distinct frames in 2 s
  EXPECT_EQ(kv.at("own_frames"), "3");
  EXPECT_EQ(kv.at("latency_ms.p50"), "40.000");  // nearest rank of {20, 40, 100}
  EXPECT_EQ(kv.at("latency_ms.p95"), "100.000");
  EXPECT_EQ(kv.at("latency_ms.max"), "100.000");
  EXPECT_EQ(kv.at("latency_ms.count"), "3");
  EXPECT_EQ(kv.at("service_latency_ms.max"), "90.000");
  EXPECT_EQ(kv.at("errors.total"), "2");
  EXPECT_EQ(kv.at("errors.Overloaded"), "2");
  EXPECT_EQ(kv.at("disconnects"), "0");
  EXPECT_EQ(kv.at("service.frames_rendered"), "4");
  EXPECT_EQ(kv.at("service.poses_received"), "399");
  EXPECT_EQ(kv.at("rss_kib.start"), "102400");
  EXPECT_EQ(kv.at("rss_kib.max"), "122880");
  EXPECT_EQ(kv.at("rss_kib.end"), "112640");
  EXPECT_EQ(kv.at("per_client.1.frames"), "3");
  EXPECT_EQ(kv.at("per_client.1.errors"), "2");
  EXPECT_EQ(kv.at("view"), "160x90");
  EXPECT_EQ(kv.at("result"), "failed: 2 Error(s) received");
  EXPECT_EQ(key_values(format_soak_report(s, true)).at("result"), "ok") << "--expect-errors";

  // The JSON carries the same figures.
  const nlohmann::json j = nlohmann::json::parse(soak_report(s, false).dump());
  EXPECT_EQ(j.at("poses_sent").get<int>(), 399);
  EXPECT_EQ(j.at("latency_ms").at("p95").get<double>(), 100.0);
  EXPECT_EQ(j.at("errors").at("Overloaded").get<int>(), 2);
  EXPECT_EQ(j.at("per_client").size(), 2u);
  EXPECT_EQ(j.at("rss_kib").at("max").get<int>(), 122880);
}

TEST(SoakReport, DisconnectsUnansweredStatsAGoneServiceAndNoFramesFail) {
  SoakSummary s = two_clients();
  s.clients[1].errors.clear();
  EXPECT_TRUE(soak_failures(s, false).empty());
  s.clients[0].disconnected = true;
  s.clients[0].disconnect_reason = "connection closed by the service: End of file";
  s.clients[1].final_stats = false;
  s.service_gone = true;
  const auto why = soak_failures(s, true);
  ASSERT_EQ(why.size(), 3u);
  EXPECT_EQ(why[0], "1 client(s) disconnected");
  EXPECT_EQ(why[1], "1 final StatsRequest(s) unanswered");
  EXPECT_EQ(why[2], "the service process (pid 4242) went away");
  const auto kv = key_values(format_soak_report(s, true));
  EXPECT_EQ(kv.at("disconnects"), "1");
  EXPECT_EQ(kv.at("drain_timeouts"), "1");
  EXPECT_EQ(kv.at("per_client.0.reason"), "connection closed by the service: End of file");
  for (auto& c : s.clients) c.frames = 0;
  EXPECT_EQ(soak_failures(s, true).back(), "no frame received");
}

}  // namespace
}  // namespace cloudsvc::sim
