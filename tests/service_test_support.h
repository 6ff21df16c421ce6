// Starts `cloudsvc serve` as a child process for integration tests (loopback/Unix socket
// only) and stops it; the process is killed if a test fails before stopping it.
#pragma once

#include <gtest/gtest.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "protocol/messages.h"

namespace cloudsvc::test {

// A loopback TCP port that was free a moment ago: the kernel picks it for a socket bound to
// 127.0.0.1:0, which is then closed (another process may take it meanwhile: callers retry).
inline int free_tcp_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = 0;
  socklen_t len = sizeof a;
  int port = -1;
  if (fd >= 0 && ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 &&
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) == 0)
    port = ntohs(a.sin_port);
  if (fd >= 0) ::close(fd);
  return port;
}

class ServiceProcess {
 public:
  enum class Tcp { No, Yes };

  // extra: further `serve` flags. Waits until the Unix socket exists. With Tcp::Yes the
  // service also listens on tcp://127.0.0.1:<free port> (tcp_address()); a port taken by
  // someone else between picking and binding is retried with another (3 tries).
  explicit ServiceProcess(const std::string& tag, std::vector<std::string> extra = {}, Tcp tcp = Tcp::No) {
    dir_ = std::filesystem::temp_directory_path() / ("cloudsvc_svc_" + tag + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    socket_ = (dir_ / "s.sock").string();
    shm_ = "cloudsvc-test-" + tag + "-" + std::to_string(::getpid());
    for (int attempt = 0; attempt < 3; ++attempt) {
      std::vector<std::string> args = {std::string(CLOUDSVC_BIN_DIR) + "/cloudsvc", "serve"};
      if (tcp == Tcp::Yes) {
        tcp_port_ = free_tcp_port();
        // first, so that it is bound before the Unix socket file (what launch() waits for) exists
        args.insert(args.end(), {"--listen", "tcp://127.0.0.1:" + std::to_string(tcp_port_)});
      }
      args.insert(args.end(), {"--listen", "unix:" + socket_, "--shm", shm_, "--shm-max-size", "256x256", "--size",
                               "64x36", "--weather", "scattered-cumulus", "--time", "2026-06-21T12:00:00Z"});
      args.insert(args.end(), extra.begin(), extra.end());
      launch(args);
      if (running() || tcp == Tcp::No) break;
    }
  }
  ~ServiceProcess() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  bool running() const { return pid_ > 0 && std::filesystem::exists(socket_); }
  std::string address() const { return "unix:" + socket_; }
  std::string tcp_address() const { return "tcp://127.0.0.1:" + std::to_string(tcp_port_); }
  int tcp_port() const { return tcp_port_; }
  const std::string& socket_path() const { return socket_; }
  const std::string& shm_name() const { return shm_; }
  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path log_path() const { return dir_ / "serve.log"; }

  // Sends `sig` without waiting (see wait_exit).
  void signal(int sig) {
    if (pid_ > 0) ::kill(pid_, sig);
  }
  // Waits up to `timeout` for the process to exit; returns its exit code (-1 if it did not
  // exit normally in time).
  int wait_exit(std::chrono::seconds timeout = std::chrono::seconds(30)) {
    if (pid_ <= 0) return -1;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return -1;
  }

  // Sends `sig` and waits up to `timeout` for the exit; returns the exit code (-1 if it did
  // not exit normally in time).
  int stop(int sig = SIGTERM, std::chrono::seconds timeout = std::chrono::seconds(30)) {
    if (pid_ <= 0) return -1;
    ::kill(pid_, sig);
    return wait_exit(timeout);
  }

 private:
  void launch(std::vector<std::string> args) {
    const std::string log = log_path().string();
    pid_ = ::fork();
    if (pid_ == 0) {
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      FILE* f = std::freopen(log.c_str(), "w", stdout);
      (void)f;
      ::dup2(::fileno(stdout), 2);
      ::execv(argv[0], argv.data());
      _exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!std::filesystem::exists(socket_) && std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  std::filesystem::path dir_;
  std::string socket_, shm_;
  int tcp_port_ = -1;
  pid_t pid_ = -1;
};

// The service tests' pose: latitude lat_deg on Zurich's meridian (8.56 E), 1500 m, heading
// east, level; sim time sim_time_s.
inline protocol::Pose test_pose(double lat_deg, double sim_time_s = 1.0) {
  protocol::Pose p;
  p.sim_time_s = sim_time_s;
  p.lat_deg = lat_deg;
  p.lon_deg = 8.56;
  p.alt_m = 1500.0;
  p.heading_deg = 90.0;
  return p;
}

// A whole text file (e.g. the service's log); empty if it cannot be read.
inline std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace cloudsvc::test
