// Output path checks of the command lines (option_paths.h).
#include "common/option_paths.h"

#include <linux/magic.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <system_error>

#include "common/option_values.h"

namespace cloudsvc::cli {

namespace fs = std::filesystem;

namespace {

// Pseudo file systems where root passes access(W_OK) but no regular file can be created.
bool is_pseudo_filesystem(const fs::path& dir) {
  struct statfs info {};
  if (statfs(dir.c_str(), &info) != 0) return false;
  return info.f_type == PROC_SUPER_MAGIC || info.f_type == SYSFS_MAGIC;
}

// True if files can be created in the existing directory `dir`.
bool is_writable_directory(const fs::path& dir) {
  return access(dir.c_str(), W_OK | X_OK) == 0 && !is_pseudo_filesystem(dir);
}

// Deepest existing directory on the way to `path` (which does not exist).
fs::path nearest_existing_ancestor(const fs::path& path) {
  std::error_code ec;
  fs::path current = fs::absolute(path, ec).lexically_normal();
  while (!fs::exists(current, ec) && current.has_parent_path() &&
         current.parent_path() != current) {
    current = current.parent_path();
  }
  return current;
}

}  // namespace

void require_writable_directory(std::string_view flag, const std::string& value,
                                const fs::path& dir) {
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (!fs::exists(status)) fail(flag, value, "directory " + dir.string() + " does not exist");
  if (!fs::is_directory(status)) fail(flag, value, dir.string() + " is not a directory");
  if (!is_writable_directory(dir)) {
    fail(flag, value, "directory " + dir.string() + " is not writable");
  }
}

void check_writable_file(std::string_view flag, const std::string& path) {
  const fs::path file(path);
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  require_writable_directory(flag, path, dir);
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (fs::is_directory(status)) fail(flag, path, "is a directory");
  if (fs::exists(status) && access(file.c_str(), W_OK) != 0) {
    fail(flag, path, "existing file is not writable");
  }
}

void check_output_file(std::string_view flag, const std::string& path) {
  const std::string name = fs::path(path).filename().string();
  const bool known_extension = ends_with_ci(name, ".png") || ends_with_ci(name, ".exr");
  if (!known_extension || name.size() <= 4) {
    fail(flag, path, "expected a file name ending in .png (8-bit sRGB) or .exr (linear 32-bit float)");
  }
  check_writable_file(flag, path);
}

void check_output_directory(std::string_view flag, const std::string& dir_text) {
  if (dir_text.empty()) fail(flag, dir_text, "expected a directory path");
  const fs::path dir(dir_text);
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (fs::exists(status)) {
    if (!fs::is_directory(status)) fail(flag, dir_text, "exists and is not a directory");
    if (!is_writable_directory(dir)) fail(flag, dir_text, "directory is not writable");
    return;
  }
  const fs::path ancestor = nearest_existing_ancestor(dir);
  if (!fs::is_directory(ancestor, ec)) {
    fail(flag, dir_text, ancestor.string() + " is not a directory");
  }
  if (!is_writable_directory(ancestor)) {
    fail(flag, dir_text, "parent directory " + ancestor.string() + " is not writable");
  }
}

}  // namespace cloudsvc::cli
