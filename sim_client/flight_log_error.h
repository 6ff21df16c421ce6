// The one exception type of the flight-log readers.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace cloudsvc::sim {

// A flight log that cannot be turned into a pose track. what() is a single line
//   <file>:<line>: <problem>
// with <line> 1-based (the first line of a logical line for ACMI continuations). Line 0
// means the file as a whole: it cannot be opened, its extension or compression is not
// supported, or the requested ACMI object cannot be chosen. Line breaks inside the
// problem text are replaced by spaces so the message stays on one line.
class FlightLogError : public std::runtime_error {
 public:
  FlightLogError(const std::string& file, std::size_t line, const std::string& problem);

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_;
  std::size_t line_;
  std::string problem_;
};

}  // namespace cloudsvc::sim
