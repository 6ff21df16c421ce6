// The two kinds of failure of a sim_client command (sim_client_main.cpp maps them to exit
// codes, common/option_values.h). A bad flag value is cli::FlagError (option_values.h),
// also exit code 2.
#pragma once

#include <stdexcept>

namespace cloudsvc::sim {

// Bad input: a flag combination or an input file (exit code 2). what() is one line.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Failure after the input was accepted: the service refused something, a file write
// failed (exit code 1).
struct RunError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace cloudsvc::sim
