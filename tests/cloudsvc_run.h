// Runs the cloudsvc and sim_client executables with arguments, its stdout and stderr captured in files of a
// test's directory (end-to-end tests of the command line).
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace cloudsvc::test {

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

// Single-quoted for /bin/sh.
inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// `program args...` from the build's bin directory; `dir` holds the captured streams.
inline RunResult run_program(const std::string& program, const std::vector<std::string>& args,
                             const std::filesystem::path& dir) {
  std::string cmd = shell_quote(std::string(CLOUDSVC_BIN_DIR) + "/" + program);
  // appended piecewise: GCC 12's -Wrestrict misfires on "literal" + std::string&& here
  for (const auto& a : args) {
    cmd += ' ';
    cmd += shell_quote(a);
  }
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  cmd += " >";
  cmd += shell_quote(out.string());
  cmd += " 2>";
  cmd += shell_quote(err.string());
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  const auto slurp = [](const std::filesystem::path& p) {
    std::ifstream f(p);
    return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  };
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

inline RunResult run_cloudsvc(const std::vector<std::string>& args, const std::filesystem::path& dir) {
  return run_program("cloudsvc", args, dir);
}

inline RunResult run_sim_client(const std::vector<std::string>& args, const std::filesystem::path& dir) {
  return run_program("sim_client", args, dir);
}

}  // namespace cloudsvc::test
