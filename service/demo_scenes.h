// The documented demo scene set rendered by `cloudsvc demo` (README command 1), listed in
// the README ("Demo scenes") and defined in demo_scenes.cpp.
#pragma once

#include <string>
#include <vector>

#include "geodesy/geodetic.h"

namespace cloudsvc {

struct DemoScene {
  std::string name;         // file stem in the output folder
  std::string description;  // one line for the README / logs
  geo::Geodetic position;
  geo::Attitude attitude;
  std::string time_utc;     // ISO 8601
  double fov_deg;
  std::string weather;      // preset name
};

const std::vector<DemoScene>& demo_scenes();

}  // namespace cloudsvc
