// Progress of a long run (replay, sweep) on stderr: a bar redrawn in place when stderr is
// a terminal, otherwise one line per 10 % so that logs stay readable.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>

namespace cloudsvc::sim {

// "0:07", "12:34", "1:02:03" (hours:minutes:seconds, rounded down to whole seconds); "--:--"
// for a negative or non-finite duration.
std::string format_duration(double seconds);

// "[###############---------------]  50/100 frames  50%  12.5 frames/s  ETA 0:04"
// elapsed_s: wall time since the start, s; unit: what is counted ("frames", "poses"). The
// rate and ETA are left out while nothing is done yet; done is clamped to total;
// bar_width >= 1 characters.
std::string format_progress_bar(std::size_t done, std::size_t total, double elapsed_s, int bar_width = 30,
                                const std::string& unit = "frames");

// "replay: 50% (50/100 frames, 4.0 s)"
std::string format_progress_line(const std::string& label, std::size_t done, std::size_t total, double elapsed_s,
                                 const std::string& unit = "frames");

class ProgressReporter {
 public:
  // interactive: redraw a bar in place (carriage return), at most every 0.1 s; otherwise
  // print a line each time done crosses another multiple of 10 % of total.
  ProgressReporter(std::ostream& out, bool interactive, std::size_t total, std::string label,
                   std::string unit = "frames");

  // done items after elapsed_s seconds.
  void update(std::size_t done, double elapsed_s);
  // Draws the final state; the interactive bar ends its line.
  void finish(std::size_t done, double elapsed_s);

  // True when file descriptor 2 is a terminal.
  static bool stderr_is_terminal();

 private:
  std::ostream& out_;
  bool interactive_;
  std::size_t total_;
  std::string label_;
  std::string unit_;
  int last_decile_ = 0;          // non-interactive: highest multiple of 10 % printed
  double last_draw_s_ = -1.0;    // interactive: time of the last redraw, s
  bool drawn_ = false;
};

}  // namespace cloudsvc::sim
