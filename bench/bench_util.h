// Small helpers shared by the benchmark commands (cloudbench and its --cost, --sequence and
// --stability modes).
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace cloudsvc::bench {

// Median of v (the mean of the two middle values for an even count); 0 for none.
inline double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Parses "WxH" with 1 <= W, H <= 4096; false if the text is not that.
inline bool parse_frame_size(const std::string& text, int& w, int& h) {
  return std::sscanf(text.c_str(), "%dx%d", &w, &h) == 2 && w > 0 && h > 0 && w <= 4096 && h <= 4096;
}

}  // namespace cloudsvc::bench
