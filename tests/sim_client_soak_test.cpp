// `sim_client soak` against a real `cloudsvc serve` (child process, Unix socket, 64x36
// frames on llvmpipe), reduced to seconds: 2 clients x 50 Hz x 2 s through run_soak, whose
// figures must agree with the service's own Stats, then RenderRequests answered before a
// client ends; and the sim_client binary's exit code, one-line error and JSON report when
// the service is killed under a running soak.
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "service_test_support.h"
#include "sim_client/service_connection.h"
#include "sim_client/soak_run.h"

namespace cloudsvc::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using sim::SoakOptions;
using sim::SoakSummary;

TEST(SimClientSoak, TwoClientsAtFiftyHertzForTwoSecondsAgreeWithTheService) {
  ServiceProcess svc("soak");
  ASSERT_TRUE(svc.running()) << read_text_file(svc.log_path());
  SoakOptions o;
  o.addresses = {svc.address()};
  o.clients = 2;
  o.rate_hz = 50.0;
  o.duration_s = 2.0;
  o.width = 64;
  o.height = 36;
  o.service_pid = svc.pid();
  const SoakSummary s = sim::run_soak(o);
  const std::string report = sim::format_soak_report(s, false);
  SCOPED_TRACE(report);
  EXPECT_TRUE(sim::soak_failures(s, false).empty());
  EXPECT_NE(report.find("\nresult=ok\n"), std::string::npos);
  EXPECT_TRUE(s.view_sent) << "the test service has a shared-memory ring: the view is set";
  EXPECT_GE(s.threads, 1u);
  EXPECT_DOUBLE_EQ(s.run_s, 2.0);
  ASSERT_EQ(s.clients.size(), 2u);
  std::uint64_t poses = 0, own = 0;
  for (const sim::SoakClientStats& c : s.clients) {
    // Pose k is due at k / 50 s < 2 s: 100 poses; a late timer catches up, so all are sent.
    EXPECT_EQ(c.poses_sent, 100u);
    EXPECT_EQ(c.poses_skipped, 0u);
    EXPECT_EQ(c.requests_sent, 0u);
    EXPECT_GT(c.frames, 0u);
    EXPECT_EQ(c.frames, c.frame_numbers.size());
    EXPECT_TRUE(c.errors.empty());
    EXPECT_FALSE(c.disconnected) << c.disconnect_reason;
    EXPECT_TRUE(c.final_stats);
    EXPECT_EQ(c.latency_ms.size(), c.own_frames);
    for (double ms : c.latency_ms) {
      EXPECT_GT(ms, 0.0);
      EXPECT_LT(ms, 60000.0);
    }
    poses += c.poses_sent;
    own += c.own_frames;
  }
  EXPECT_GT(own, 0u) << "some frames show the clients' own poses";
  // The service's counters over the run: every pose arrived (the final Stats of the later
  // client is answered after both clients' last poses), and it rendered every frame the
  // clients saw.
  ASSERT_TRUE(s.service_start && s.service_end);
  EXPECT_EQ(s.service_end->poses_received - s.service_start->poses_received, poses);
  const nlohmann::json j = nlohmann::json::parse(sim::soak_report(s, false).dump());
  EXPECT_GT(j.at("frames_distinct").get<std::uint64_t>(), 0u);
  EXPECT_LE(j.at("frames_distinct").get<std::uint64_t>(), j.at("service").at("frames_rendered").get<std::uint64_t>());
  EXPECT_GT(j.at("frame_rate_hz").get<double>(), 0.0);
  EXPECT_LE(j.at("latency_ms").at("p50").get<double>(), j.at("latency_ms").at("max").get<double>());
  // VmRSS: before, once a second, after; a GL service holds more than 10 MiB.
  EXPECT_GE(s.rss.samples, 3u);
  EXPECT_GT(s.rss.start, 10u * 1024 * 1024);
  EXPECT_GE(s.rss.max, s.rss.start);
  EXPECT_GE(s.rss.max, s.rss.end);
  EXPECT_FALSE(s.service_gone);

  // RenderRequests: one after every 10th pose, 2 in all (the service refuses a third
  // pending one per client with Overloaded, which 2 cannot reach). A client ends only
  // when each has its FrameReady, so both are counted, with their latency.
  SoakOptions r = o;
  r.clients = 1;
  r.rate_hz = 10.0;
  r.render_every = 10;
  r.service_pid = 0;
  const SoakSummary q = sim::run_soak(r);
  SCOPED_TRACE(sim::format_soak_report(q, false));
  EXPECT_TRUE(sim::soak_failures(q, false).empty());
  ASSERT_EQ(q.clients.size(), 1u);
  EXPECT_EQ(q.clients[0].poses_sent, 20u);
  EXPECT_EQ(q.clients[0].requests_sent, 2u);
  EXPECT_EQ(q.clients[0].request_frames, 2u);
  EXPECT_EQ(q.clients[0].request_latency_ms.size(), 2u);
  EXPECT_EQ(q.clients[0].frames, q.clients[0].frame_numbers.size() + 2);
  EXPECT_EQ(q.rss.samples, 0u) << "no --service-pid, no samples";
  EXPECT_EQ(svc.stop(), 0);
}

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

// Runs build/bin/sim_client with `args` (no shell quoting: the tests' paths have no
// spaces), stdout and stderr captured into files of `dir`.
RunResult run_sim_client(const fs::path& dir, const std::string& args) {
  const fs::path out = dir / "soak_out.txt", err = dir / "soak_err.txt";
  const std::string cmd = std::string(CLOUDSVC_BIN_DIR) + "/sim_client " + args + " > " + out.string() + " 2> " + err.string();
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text_file(out);
  r.err = read_text_file(err);
  return r;
}

std::string last_line(const std::string& text) {
  std::istringstream in(text);
  std::string line, last;
  while (std::getline(in, line)) last = line;
  return last;
}

TEST(SimClientSoak, ExitsOneWithOneLineWhenTheServiceDiesUnderIt) {
  ServiceProcess svc("soak_kill");
  ASSERT_TRUE(svc.running()) << read_text_file(svc.log_path());
  const fs::path json = svc.dir() / "report.json";
  RunResult r;
  std::thread soak([&] {
    r = run_sim_client(svc.dir(), "soak --connect " + svc.address() + " --clients 2 --rate 50 --duration 10m --size 64x36 " +
                                      "--service-pid " + std::to_string(svc.pid()) + " --json " + json.string());
  });
  // The soak is flying once both of its clients are connected and the service has had
  // more poses than the one warm-up pose: asked of the service itself, not guessed.
  bool flying = false;
  {
    client::ServiceConnection watcher(svc.address(), "soak-test watcher");
    const auto give_up = std::chrono::steady_clock::now() + 180s;
    while (!flying && std::chrono::steady_clock::now() < give_up) {
      watcher.send(protocol::StatsRequest{});
      const auto stats = watcher.receive_until<protocol::Stats>(30s);
      flying = stats.clients == 3 && stats.poses_received > 10;
      if (!flying) std::this_thread::sleep_for(50ms);  // poll interval, not a readiness guess
    }
  }
  svc.signal(SIGKILL);
  soak.join();
  svc.wait_exit();
  ::shm_unlink(("/" + svc.shm_name()).c_str());  // a killed service leaves its ring behind
  ASSERT_TRUE(flying) << "the soak never started flying: " << r.err;
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  // The failure is the last line of stderr (progress lines, one per 10 s, may precede it).
  EXPECT_EQ(last_line(r.err).rfind("sim_client soak: failed: 2 client(s) disconnected", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("went away"), std::string::npos) << "the sampled pid vanished: " << r.err;
  EXPECT_NE(r.out.find("\ndisconnects=2\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nper_client.0.reason=connection closed by the service"), std::string::npos) << r.out;
  const nlohmann::json j = nlohmann::json::parse(read_text_file(json));
  EXPECT_EQ(j.at("disconnects").get<int>(), 2);
  EXPECT_EQ(j.at("result").get<std::string>().rfind("failed: ", 0), 0u);
  EXPECT_LT(j.at("run_s").get<double>(), 600.0) << "the run ends when every client is gone, not at --duration";
}

}  // namespace
}  // namespace cloudsvc::test
