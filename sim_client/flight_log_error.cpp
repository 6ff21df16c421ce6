// FlightLogError: "<file>:<line>: <problem>" on one line.
#include "sim_client/flight_log_error.h"

namespace cloudsvc::sim {

namespace {

std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

}  // namespace

FlightLogError::FlightLogError(const std::string& file, std::size_t line,
                               const std::string& problem)
    : std::runtime_error(one_line(file) + ":" + std::to_string(line) + ": " + one_line(problem)),
      file_(file),
      line_(line),
      problem_(one_line(problem)) {}

}  // namespace cloudsvc::sim
