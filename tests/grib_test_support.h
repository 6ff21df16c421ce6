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

// Appends a field of one value given by its GRIB2 numbers (discipline 0, parameter category
// and number, type of first fixed surface) on the regular_ll sample (0-30 E, 0-60 N, 2
// degrees), from 2026-06-01 00 UTC + `hour` hours.
inline void append_cloud_field(const std::filesystem::path& file, long category, long number, long level_type,
                               double value, long hour) {
  append_grib_message(file, "regular_ll_sfc_grib2",
                      {{"discipline", 0L}, {"parameterCategory", category}, {"parameterNumber", number},
                       {"typeOfFirstFixedSurface", level_type}, {"dataDate", 20260601L}, {"dataTime", 0L},
                       {"stepRange", std::to_string(hour)}},
                      [value](double, double) { return value; });
}

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
