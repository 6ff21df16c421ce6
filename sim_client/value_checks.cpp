// Range and finiteness checks with one-line problem texts.
#include "sim_client/value_checks.h"

#include <cmath>

#include "sim_client/text_input.h"

namespace cloudsvc::sim {

std::optional<std::string> finite_problem(std::string_view name, double v) {
  if (std::isfinite(v)) return std::nullopt;
  return std::string(name) + " is not finite (" + format_number(v) + ")";
}

std::optional<std::string> range_problem(std::string_view name, double v, double lo, double hi) {
  if (auto p = finite_problem(name, v)) return p;
  if (v >= lo && v <= hi) return std::nullopt;
  return std::string(name) + " " + format_number(v) + " out of range [" + format_number(lo) +
         ", " + format_number(hi) + "]";
}

}  // namespace cloudsvc::sim
