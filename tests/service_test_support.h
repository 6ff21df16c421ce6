// Starts `cloudsvc serve` as a child process for integration tests (loopback/Unix socket
// only), waits until it reports readiness, and stops it; the process is killed if a test
// fails before stopping it.
#pragma once

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <utility>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "protocol/messages.h"

namespace cloudsvc::test {

// A whole text file (e.g. the service's log); empty if it cannot be read.
inline std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

class ServiceProcess {
 public:
  enum class Tcp { No, Yes };
  enum class OutDir { No, Yes };

  // extra: further `serve` flags. The service writes --ready-file once every listener is
  // bound; the constructor waits for that file (or the process's exit), so a test never
  // guesses when the service is ready. With Tcp::Yes the service also listens on
  // tcp://127.0.0.1:0 and the port the kernel chose is read from the ready file. With
  // OutDir::Yes it runs with --out-dir out_dir() (the only place clients may have it write).
  explicit ServiceProcess(const std::string& tag, std::vector<std::string> extra = {}, Tcp tcp = Tcp::No,
                          OutDir out = OutDir::No) {
    dir_ = std::filesystem::temp_directory_path() / ("cloudsvc_svc_" + tag + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    socket_ = (dir_ / "s.sock").string();
    shm_ = "cloudsvc-test-" + tag + "-" + std::to_string(::getpid());
    std::vector<std::string> args = {std::string(CLOUDSVC_BIN_DIR) + "/cloudsvc", "serve"};
    if (tcp == Tcp::Yes) args.insert(args.end(), {"--listen", "tcp://127.0.0.1:0"});
    args.insert(args.end(), {"--listen", "unix:" + socket_, "--ready-file", ready_path().string(), "--shm", shm_,
                             "--size", "64x36"});
    // defaults a test may give otherwise
    for (const auto& [flag, value] : {std::pair{"--time", "2026-06-21T12:00:00Z"}, std::pair{"--weather", "scattered-cumulus"}})
      if (std::find(extra.begin(), extra.end(), flag) == extra.end()) args.insert(args.end(), {flag, value});
    if (std::find(extra.begin(), extra.end(), "--shm-max-size") == extra.end())
      args.insert(args.end(), {"--shm-max-size", "256x256"});
    if (out == OutDir::Yes) {
      std::filesystem::create_directories(out_dir());
      args.insert(args.end(), {"--out-dir", out_dir().string()});
    }
    args.insert(args.end(), extra.begin(), extra.end());
    launch(args);
    if (tcp == Tcp::Yes && ready_) {
      const std::string text = read_text_file(ready_path());
      const auto at = text.find("tcp://127.0.0.1:");
      if (at != std::string::npos) tcp_port_ = std::stoi(text.substr(at + 16));
    }
  }
  ~ServiceProcess() {
    if (pid_ > 0) {  // not stopped by the test: killed, so it cannot remove its frame segment
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
      ::shm_unlink(("/" + shm_).c_str());
    }
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  // Ready (every listener bound) and not exited since.
  bool running() const { return ready_ && pid_ > 0 && std::filesystem::exists(socket_); }
  std::string address() const { return "unix:" + socket_; }
  std::string tcp_address() const { return "tcp://127.0.0.1:" + std::to_string(tcp_port_); }
  int tcp_port() const { return tcp_port_; }
  pid_t pid() const { return pid_; }
  const std::string& socket_path() const { return socket_; }
  const std::string& shm_name() const { return shm_; }
  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path out_dir() const { return dir_ / "out"; }
  std::filesystem::path log_path() const { return dir_ / "serve.log"; }
  std::filesystem::path ready_path() const { return dir_ / "ready"; }

  // Sends `sig` without waiting (see wait_exit).
  void signal(int sig) {
    if (pid_ > 0) ::kill(pid_, sig);
  }
  // Waits up to `timeout` for the process to exit; returns its exit code (-1 if it did not
  // exit normally in time).
  int wait_exit(std::chrono::seconds timeout = std::chrono::seconds(30)) {
    if (pid_ <= 0) return exit_code_;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
      if (reap()) return exit_code_;
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
  // True once the child has exited (and was reaped); exit_code_ is then its exit code.
  bool reap() {
    int status = 0;
    if (pid_ <= 0) return true;
    if (::waitpid(pid_, &status, WNOHANG) != pid_) return false;
    pid_ = -1;
    exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return true;
  }

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
    // Readiness is the ready file (written by rename once every listener is bound); the
    // deadline only bounds a service that never gets there.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (!(ready_ = std::filesystem::exists(ready_path())) && std::chrono::steady_clock::now() < deadline) {
      if (reap()) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  std::filesystem::path dir_;
  std::string socket_, shm_;
  int tcp_port_ = -1;
  pid_t pid_ = -1;
  int exit_code_ = -1;
  bool ready_ = false;
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


}  // namespace cloudsvc::test
