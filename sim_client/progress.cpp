// Progress bar and progress lines (progress.h).
#include "sim_client/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cloudsvc::sim {

namespace {
constexpr double kRedrawInterval_s = 0.1;
}

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "--:--";
  const long long total = static_cast<long long>(std::floor(seconds));
  const long long h = total / 3600, m = (total / 60) % 60, s = total % 60;
  char buf[48];
  if (h > 0) std::snprintf(buf, sizeof buf, "%lld:%02lld:%02lld", h, m, s);
  else std::snprintf(buf, sizeof buf, "%lld:%02lld", m, s);
  return buf;
}

std::string format_progress_bar(std::size_t done, std::size_t total, double elapsed_s, int bar_width,
                                const std::string& unit) {
  done = std::min(done, total);
  bar_width = std::max(bar_width, 1);
  const double fraction = total == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total);
  const int filled = static_cast<int>(std::floor(fraction * bar_width));
  std::string out = "[";
  out.append(static_cast<std::size_t>(filled), '#');
  out.append(static_cast<std::size_t>(bar_width - filled), '-');
  out += ']';
  char buf[160];
  std::snprintf(buf, sizeof buf, "  %zu/%zu %s  %3d%%", done, total, unit.c_str(),
                static_cast<int>(std::floor(fraction * 100.0)));
  out += buf;
  if (done > 0 && elapsed_s > 0.0) {
    const double rate = static_cast<double>(done) / elapsed_s;  // frames/s
    std::snprintf(buf, sizeof buf, "  %.1f %s/s  ETA %s", rate, unit.c_str(),
                  format_duration(static_cast<double>(total - done) / rate).c_str());
    out += buf;
  }
  return out;
}

std::string format_progress_line(const std::string& label, std::size_t done, std::size_t total, double elapsed_s,
                                 const std::string& unit) {
  done = std::min(done, total);
  const int percent = total == 0 ? 100 : static_cast<int>(done * 100 / total);
  char buf[160];
  std::snprintf(buf, sizeof buf, ": %d%% (%zu/%zu %s, %.1f s)", percent, done, total, unit.c_str(), elapsed_s);
  return label + buf;
}

ProgressReporter::ProgressReporter(std::ostream& out, bool interactive, std::size_t total, std::string label,
                                   std::string unit)
    : out_(out), interactive_(interactive), total_(total), label_(std::move(label)), unit_(std::move(unit)) {}

void ProgressReporter::update(std::size_t done, double elapsed_s) {
  if (interactive_) {
    if (drawn_ && elapsed_s - last_draw_s_ < kRedrawInterval_s && done < total_) return;
    out_ << '\r' << label_ << ' ' << format_progress_bar(done, total_, elapsed_s, 30, unit_) << "\x1b[K" << std::flush;
    last_draw_s_ = elapsed_s;
    drawn_ = true;
    return;
  }
  const int decile = total_ == 0 ? 10 : static_cast<int>(std::min(done, total_) * 10 / total_);
  if (decile > last_decile_) {
    last_decile_ = decile;
    out_ << format_progress_line(label_, done, total_, elapsed_s, unit_) << '\n' << std::flush;
  }
}

void ProgressReporter::finish(std::size_t done, double elapsed_s) {
  if (interactive_) {
    drawn_ = false;  // force the last redraw
    update(done, elapsed_s);
    out_ << '\n' << std::flush;
  } else {
    update(done, elapsed_s);
  }
}

bool ProgressReporter::stderr_is_terminal() { return ::isatty(2) == 1; }

}  // namespace cloudsvc::sim
