#include "service/output_directory.h"

#include <unistd.h>

#include <algorithm>
#include <system_error>

namespace cloudsvc {

namespace fs = std::filesystem;

namespace {

// True when `inner` is `outer` or below it; both canonical.
bool is_within(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i) {
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

}  // namespace

ClientDirectory resolve_client_directory(const std::string& requested, const std::string& root) {
  ClientDirectory out;
  const std::string quoted = "'" + requested + "'";
  if (root.empty()) {
    out.problem = "SetView.file_dir " + quoted +
                  ": the service was started without --out-dir, so no client may choose where it writes files";
    return out;
  }
  std::error_code ec;
  const fs::path canonical_root = fs::canonical(root, ec);
  if (ec) {
    out.problem = "SetView.file_dir " + quoted + ": the service's --out-dir " + root + " is gone: " + ec.message();
    return out;
  }
  const fs::path asked(requested);
  const fs::path joined = asked.is_absolute() ? asked : canonical_root / asked;
  const fs::path resolved = fs::canonical(joined, ec);  // follows every link; fails if absent
  if (ec || !fs::is_directory(resolved, ec)) {
    out.problem = "SetView.file_dir " + quoted + ": not an existing directory on the service's machine";
    return out;
  }
  if (!is_within(resolved, canonical_root)) {
    out.problem = "SetView.file_dir " + quoted + ": outside the service's --out-dir " + canonical_root.string() +
                  " (relative paths are taken from there; links may not lead out of it)";
    return out;
  }
  if (::access(resolved.c_str(), W_OK) != 0) {
    out.problem = "SetView.file_dir " + quoted + ": not writable by the service";
    return out;
  }
  out.path = resolved;
  return out;
}

}  // namespace cloudsvc
