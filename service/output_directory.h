// Where a network client may have the file sink write: only inside the directory the
// operator named with `cloudsvc serve --out-dir` (docs/RELIABILITY.md, threat model). A
// client must not be able to make the service write into any other directory the service's
// user can write (`../`, absolute paths elsewhere, symbolic links leading out).
#pragma once

#include <filesystem>
#include <string>
#include <variant>

namespace cloudsvc {

// A directory resolved against the operator's root, or the reason it is refused.
struct ClientDirectory {
  std::filesystem::path path;  // canonical (absolute, no symbolic links, no . or ..)
  std::string problem;         // empty when path may be written
};

// Resolves `requested` (SetView.file_dir: relative to `root`, or absolute) and accepts it
// only when it is an existing, writable directory that is `root` or lies below it after
// every symbolic link is resolved. An empty `root` (no --out-dir) refuses every request.
ClientDirectory resolve_client_directory(const std::string& requested, const std::string& root);

}  // namespace cloudsvc
