// `cloudsvc serve --window` under a virtual X server (xvfb-run, installed by
// scripts/install-deps.sh): the render thread owns the window's GL context, a pose gives a
// FrameReady, and --exit-after-frames stops the service cleanly (exit 0).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "sim_client/service_connection.h"

namespace {

using namespace std::chrono_literals;

TEST(ServiceWindow, RendersIntoAWindowUnderXvfb) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run not installed";
  const auto dir = std::filesystem::temp_directory_path() / ("cloudsvc_win_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string sock = (dir / "s.sock").string();
  const std::string log = (dir / "serve.log").string();
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string bin = std::string(CLOUDSVC_BIN_DIR) + "/cloudsvc";
    std::freopen(log.c_str(), "w", stdout);
    ::dup2(::fileno(stdout), 2);
    ::execlp("xvfb-run", "xvfb-run", "-a", bin.c_str(), "serve", "--window", "--listen", ("unix:" + sock).c_str(),
             "--size", "64x36", "--exit-after-frames", "2", static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int i = 0; i < 600 && !std::filesystem::exists(sock); ++i) std::this_thread::sleep_for(50ms);
  ASSERT_TRUE(std::filesystem::exists(sock)) << "service did not start";
  {
    cloudsvc::client::ServiceConnection c("unix:" + sock, "window-test", 30000ms);
    EXPECT_TRUE(c.welcome().capabilities & cloudsvc::protocol::capability::kSinkWindow);
    cloudsvc::protocol::SetView v;
    v.width = 64;
    v.height = 36;
    v.sinks = cloudsvc::protocol::sink::kWindow;
    c.send(v);
    for (int i = 0; i < 2; ++i) {
      cloudsvc::protocol::Pose p;
      p.sim_time_s = i;
      p.lat_deg = 47.45;
      p.lon_deg = 8.56;
      p.alt_m = 1500.0;
      p.heading_deg = 90.0;
      c.send(p);
      const auto ready = c.receive_until<cloudsvc::protocol::FrameReady>(60s);
      EXPECT_EQ(ready.frame_number, static_cast<std::uint64_t>(i + 1));
    }
  }
  int status = 0;
  for (int i = 0; i < 600 && ::waitpid(pid, &status, WNOHANG) == 0; ++i) std::this_thread::sleep_for(50ms);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "exit status " << status;
  EXPECT_FALSE(std::filesystem::exists(sock)) << "socket file removed";
  std::filesystem::remove_all(dir);
}

}  // namespace
