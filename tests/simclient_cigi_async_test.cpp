// `sim_client cigi --mode async` against a stand-in IG on a loopback UDP port the kernel
// chose: the host paces its frames at --fps but does not wait a further 1 / fps after the
// last one (at --fps 0.05 and one frame it had sat idle for 20 s before finishing; at
// --fps 0.001, 1000 s).
#include <gtest/gtest.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "protocol/cigi/cigi_datagram.h"
#include "sim_client/commands.h"

namespace cloudsvc::sim {
namespace {

namespace fs = std::filesystem;

// An IG that answers every usable host datagram with a Start of Frame naming its host frame.
class StandInIg {
 public:
  StandInIg() {
    fd_ = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = 0;  // the kernel picks
    if (fd_ < 0 || ::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) return;
    socklen_t len = sizeof a;
    ::getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &len);
    port_ = ntohs(a.sin_port);
    thread_ = std::thread([this] { serve(); });
  }
  ~StandInIg() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    if (fd_ >= 0) ::close(fd_);
  }
  int port() const { return port_; }
  int frames() const { return frames_; }

 private:
  void serve() {
    std::vector<std::uint8_t> buf(65536);
    std::uint32_t ig_frame = 0;
    while (!stop_) {
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;  // ms: wakes to see stop_
      sockaddr_in from{};
      socklen_t len = sizeof from;
      const ssize_t n = ::recvfrom(fd_, buf.data(), buf.size(), 0, reinterpret_cast<sockaddr*>(&from), &len);
      if (n <= 0) continue;
      const cigi::HostDatagram d = cigi::read_host_datagram(std::span(buf.data(), static_cast<std::size_t>(n)));
      if (!d.usable) continue;
      ++frames_;
      cigi::StartOfFrame sof;
      sof.ig_frame = ++ig_frame;
      sof.last_host_frame = d.ig_control.host_frame;
      cigi::DatagramWriter w(d.order);
      w.add(sof);
      ::sendto(fd_, w.bytes().data(), w.bytes().size(), 0, reinterpret_cast<sockaddr*>(&from), len);
    }
  }
  int fd_ = -1, port_ = 0;
  std::atomic<bool> stop_{false};
  std::atomic<int> frames_{0};
  std::thread thread_;
};

TEST(SimClientCigiAsync, DoesNotWaitAFramePeriodAfterTheLastFrame) {
  const fs::path dir = fs::temp_directory_path() / ("cloudsvc_cigi_async_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path log = dir / "two.csv";
  std::ofstream(log) << "time,lat,lon,alt,heading,pitch,roll\n"
                        "2026-06-21T12:00:00Z,47.45,8.56,2500,270,5,0\n"
                        "2026-06-21T12:00:40Z,47.45,8.55,2500,270,5,0\n";
  StandInIg ig;
  ASSERT_GT(ig.port(), 0);
  CLI::App app("test", "sim_client");
  const Command cigi = add_cigi_command(app);
  // 0.05 Hz over 40 s of log: host frames at 0 s and 20 s of log time (and of wall time).
  // Only one is sent (--max-frames 1), so there is nothing to pace.
  std::vector<std::string> args{"sim_client", "cigi", log.string(), "--ig", "udp:127.0.0.1:" + std::to_string(ig.port()),
                                "--mode", "async", "--fps", "0.05", "--max-frames", "1", "--size", "32x18"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  app.parse(static_cast<int>(argv.size()), argv.data());
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(cigi.run(), 0);
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(elapsed_s, 10.0) << "the host waited 1 / fps = 20 s after its only frame";
  EXPECT_EQ(ig.frames(), 1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cloudsvc::sim
