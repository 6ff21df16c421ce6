// The accuracy scene set (docs/ACCURACY.md), shared by
// tests/accuracy_reference_vs_gpu_test.cpp and bench/cloudbench.cpp so that every accuracy number in docs/ACCURACY.md is measured on the
// same views. No gtest here (the benchmark includes it too).
//
// Zurich area (47.45 N 8.56 E), midsummer 2026 (solar noon ~11:26 UTC, sunset ~19:26 UTC);
// no view has the sun disk in the frame (its radiance, ~2e4 W m^-2 sr^-1 nm^-1 over the
// pixels it covers even box-filtered, would dominate every metric).
#pragma once

#include <string>
#include <vector>

#include "geodesy/utc_time.h"
#include "renderer/api/frame_image.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"

namespace cloudsvc::accuracy {

struct AccuracyScene {
  const char* name;
  const char* preset;        // weather preset (weather/presets.h)
  double alt_m, heading_deg, pitch_deg;  // m above the ellipsoid, degrees
  const char* time_utc;      // ISO 8601
  bool core;                 // one of the eight scenes (the cloudbench set)
};

inline const std::vector<AccuracyScene>& accuracy_scenes() {
  static const std::vector<AccuracyScene> s = {
      {"clear", "clear", 500.0, 200.0, 10.0, "2026-06-21T11:30:00Z", true},
      {"clear, 60 deg up, sun behind", "clear", 500.0, 20.0, 60.0, "2026-06-21T11:30:00Z", false},
      {"clear, below the sun", "clear", 500.0, 181.0, 35.0, "2026-06-21T11:30:00Z", false},
      {"scattered cumulus", "scattered-cumulus", 300.0, 200.0, 15.0, "2026-06-21T11:30:00Z", true},
      {"broken cumulus", "broken-cumulus", 500.0, 200.0, 20.0, "2026-06-21T11:30:00Z", true},
      {"overcast stratus from below", "overcast-stratus", 100.0, 90.0, 10.0, "2026-06-21T11:30:00Z", true},
      {"inside a stratus deck", "overcast-stratus", 650.0, 90.0, 0.0, "2026-06-21T11:30:00Z", true},
      {"above stratocumulus at sunset", "stratocumulus-deck", 3000.0, 270.0, -12.0, "2026-06-21T19:05:00Z", true},
      {"cumulonimbus", "cumulonimbus", 13000.0, 135.0, -15.0, "2026-06-21T14:00:00Z", true},
      {"from 30 km", "broken-cumulus", 30000.0, 180.0, -25.0, "2026-06-21T11:30:00Z", true},
  };
  return s;
}

// The scene's view at w x h pixels, 60 deg horizontal field of view, frame_index 0.
inline ViewRequest accuracy_view(const AccuracyScene& s, int w, int h) {
  ViewRequest v;
  v.position = {47.45, 8.56, s.alt_m};
  v.attitude = {s.heading_deg, s.pitch_deg, 0.0};
  v.unix_time_s = *geo::parse_utc_iso8601(s.time_utc);
  v.width = w;
  v.height = h;
  v.fov_deg = 60.0;
  return v;
}

}  // namespace cloudsvc::accuracy
