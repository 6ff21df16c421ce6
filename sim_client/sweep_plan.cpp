// Sweep files: dispatch on the extension (sweep_plan.h).
#include "sim_client/sweep_plan.h"

#include <fstream>
#include <sstream>

#include "sim_client/text_input.h"
#include "sim_client/usage_errors.h"

namespace cloudsvc::sim {

SweepPlan load_sweep(const std::string& path) {
  const bool json = path.size() >= 5 && iequals(std::string_view(path).substr(path.size() - 5), ".json");
  const bool csv = path.size() >= 4 && iequals(std::string_view(path).substr(path.size() - 4), ".csv");
  if (!json && !csv) throw UsageError(path + ": unsupported sweep file (expected .json or .csv)");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw UsageError(path + ": cannot open: is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError(path + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  const std::filesystem::path base = std::filesystem::path(path).parent_path();
  return json ? parse_sweep_json(text.str(), path, base) : parse_sweep_csv(text.str(), path, base);
}

}  // namespace cloudsvc::sim
