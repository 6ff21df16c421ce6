// Runs parse_command_line on an argument list with stdout/stderr captured (CLI tests).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "service/render_options.h"

namespace cloudsvc::test {

// Result of one parse_command_line call with its captured output streams.
struct Outcome {
  ParsedCommand cmd;
  std::string out;  // stdout
  std::string err;  // stderr
};

// args exclude the program name.
inline Outcome run(const std::vector<std::string>& args) {
  std::vector<const char*> argv{"cloudsvc"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  Outcome r;
  r.cmd = parse_command_line(static_cast<int>(argv.size()), argv.data());
  r.err = testing::internal::GetCapturedStderr();
  r.out = testing::internal::GetCapturedStdout();
  return r;
}

}  // namespace cloudsvc::test
