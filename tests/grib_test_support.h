// GRIB2 files made in tests (tests/fixtures/grib_writer.h) in a temporary directory.
#pragma once

#include <filesystem>
#include <string>
#include <system_error>

#include <unistd.h>

#include "tests/fixtures/grib_writer.h"

namespace cloudsvc::test {

using fixtures::append_grib_message;
using fixtures::GribKey;

// A directory of its own under the system's temporary directory, removed afterwards.
class GribTempDir {
 public:
  GribTempDir() {
    static int counter = 0;
    dir_ = std::filesystem::temp_directory_path() /
           ("cloudsvc_grib_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(dir_);
  }
  ~GribTempDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  GribTempDir(const GribTempDir&) = delete;
  GribTempDir& operator=(const GribTempDir&) = delete;
  std::filesystem::path file(const std::string& name) const { return dir_ / name; }

 private:
  std::filesystem::path dir_;
};

}  // namespace cloudsvc::test
