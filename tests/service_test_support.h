// Starts `cloudsvc serve` as a child process for integration tests (loopback/Unix socket
// only) and stops it; the process is killed if a test fails before stopping it.
#pragma once

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

namespace cloudsvc::test {

class ServiceProcess {
 public:
  // extra: further `serve` flags. Waits until the Unix socket exists.
  explicit ServiceProcess(const std::string& tag, std::vector<std::string> extra = {}) {
    dir_ = std::filesystem::temp_directory_path() / ("cloudsvc_svc_" + tag + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    socket_ = (dir_ / "s.sock").string();
    shm_ = "cloudsvc-test-" + tag + "-" + std::to_string(::getpid());
    std::vector<std::string> args = {std::string(CLOUDSVC_BIN_DIR) + "/cloudsvc", "serve", "--listen", "unix:" + socket_,
                                     "--shm", shm_, "--shm-max-size", "256x256", "--size", "64x36",
                                     "--weather", "scattered-cumulus", "--time", "2026-06-21T12:00:00Z"};
    args.insert(args.end(), extra.begin(), extra.end());
    const std::string log = (dir_ / "serve.log").string();
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
  const std::string& socket_path() const { return socket_; }
  const std::string& shm_name() const { return shm_; }
  const std::filesystem::path& dir() const { return dir_; }

  // Sends `sig` and waits up to `timeout` for the exit; returns the exit code (-1 if it did
  // not exit normally in time).
  int stop(int sig = SIGTERM, std::chrono::seconds timeout = std::chrono::seconds(30)) {
    if (pid_ <= 0) return -1;
    ::kill(pid_, sig);
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

 private:
  std::filesystem::path dir_;
  std::string socket_, shm_;
  pid_t pid_ = -1;
};

}  // namespace cloudsvc::test
