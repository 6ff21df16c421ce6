// cloudbench's scene sets (`--scenes core|random:SEED:N`) and the key of a scene's cached
// reference image. Header-only: every bench/*.cpp is an executable.
//
//   core           the eight core scenes of tests/fixtures/accuracy_scenes.h (the default)
//   random:SEED:N  scenes 0..N-1 of seed SEED of tests/fixtures/random_scenes.h (distribution
//                  documented there): unseen views, for checking that the presets chosen on
//                  the core scenes hold elsewhere
#pragma once

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "geodesy/solar_position.h"
#include "geodesy/utc_time.h"
#include "renderer/api/view_request.h"
#include "tests/fixtures/accuracy_scenes.h"
#include "tests/fixtures/random_scenes.h"
#include "weather/cloud_layer.h"
#include "weather/presets.h"

namespace cloudsvc::bench {

inline constexpr int kMaxRandomScenes = 10000;

struct SceneSetSpec {
  bool random = false;     // false: the core scenes
  std::uint64_t seed = 0;  // random only
  int count = 0;           // random only
};

// "core" or "random:SEED:N" (SEED a decimal unsigned 64-bit integer, N in 1..kMaxRandomScenes);
// nullopt for anything else.
inline std::optional<SceneSetSpec> parse_scene_set(const std::string& text) {
  if (text == "core") return SceneSetSpec{};
  const std::string prefix = "random:";
  if (text.rfind(prefix, 0) != 0) return std::nullopt;
  const std::string rest = text.substr(prefix.size());
  const size_t colon = rest.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 >= rest.size()) return std::nullopt;
  SceneSetSpec s;
  s.random = true;
  const char* a = rest.data();
  const auto r1 = std::from_chars(a, a + colon, s.seed);
  if (r1.ec != std::errc() || r1.ptr != a + colon) return std::nullopt;
  const char* b = rest.data() + colon + 1;
  const char* e = rest.data() + rest.size();
  const auto r2 = std::from_chars(b, e, s.count);
  if (r2.ec != std::errc() || r2.ptr != e || s.count < 1 || s.count > kMaxRandomScenes) return std::nullopt;
  return s;
}

// One scene as cloudbench measures it.
struct BenchScene {
  std::string name;
  ViewRequest view;          // at the error size, frame_index 0
  weather::Weather weather;
  std::string weather_label;  // the preset name, or the random layers in one line
  double sun_elevation_deg = 0.0, sun_azimuth_deg = 0.0;  // geometric (geo::solar_position)
  bool inside_layer = false;  // camera inside a layer's altitude band [base, top]
};

inline std::vector<BenchScene> make_scene_set(const SceneSetSpec& spec, int w, int h) {
  std::vector<BenchScene> out;
  if (!spec.random) {
    for (const accuracy::AccuracyScene& s : accuracy::accuracy_scenes()) {
      if (!s.core) continue;
      BenchScene b;
      b.name = s.name;
      b.view = accuracy::accuracy_view(s, w, h);
      b.weather = *weather::preset(s.preset);
      b.weather_label = s.preset;
      const geo::SolarPosition sun =
          geo::solar_position(b.view.unix_time_s, b.view.position.lat_deg, b.view.position.lon_deg);
      b.sun_elevation_deg = sun.elevation_deg;
      b.sun_azimuth_deg = sun.azimuth_deg;
      for (const weather::CloudLayer& l : b.weather.layers)
        b.inside_layer = b.inside_layer || (s.alt_m >= l.base_m && s.alt_m <= l.top_m);
      out.push_back(b);
    }
    return out;
  }
  for (const accuracy::RandomScene& s : accuracy::random_scenes(spec.seed, spec.count)) {
    BenchScene b;
    b.name = s.name;
    b.view = accuracy::random_scene_view(s, w, h);
    b.weather = s.weather;
    b.weather_label = accuracy::describe_weather(s);
    b.sun_elevation_deg = s.sun_elevation_deg;
    b.sun_azimuth_deg = s.sun_azimuth_deg;
    b.inside_layer = s.inside_layer >= 0;
    out.push_back(b);
  }
  return out;
}

// Everything the reference image of a scene depends on besides the code: the view (position,
// attitude, time, field of view, size), the reference's rays per pixel, every field of the
// weather and the traits of each layer's cloud type (profile, noise, anvil: tuned as the
// model evolves), printed at full double precision. Two scenes share a cached reference
// only if their keys are equal.
inline std::string reference_key(const BenchScene& s, int ref_samples) {
  const ViewRequest& v = s.view;
  char b[512];
  std::snprintf(b, sizeof b, "v1 pos %.17g %.17g %.17g att %.17g %.17g %.17g t %.17g fov %.17g size %dx%d ss %d seed %u",
                v.position.lat_deg, v.position.lon_deg, v.position.alt_m, v.attitude.heading_deg, v.attitude.pitch_deg,
                v.attitude.roll_deg, v.unix_time_s, v.fov_deg, v.width, v.height, ref_samples,
                static_cast<unsigned>(s.weather.map_seed));
  std::string key = b;
  if (s.weather.ground_albedo) {  // (absent: the keys of the caches written before it existed)
    std::snprintf(b, sizeof b, " ground albedo %.17g", *s.weather.ground_albedo);
    key += b;
  }
  for (const weather::CloudLayer& l : s.weather.layers) {
    std::snprintf(b, sizeof b, " | %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g", static_cast<int>(l.type), l.base_m,
                  l.top_m, l.coverage, l.density_scale, l.droplet_diameter_um, l.wind.east_mps, l.wind.north_mps);
    key += b;
    const weather::CloudTypeTraits& t = weather::cloud_type_traits(l.type);
    std::snprintf(b, sizeof b, " traits %.9g %.9g %.9g %.9g %.17g %.17g %d anvil %.9g %.9g %.9g %.9g", t.profile.bottom_ramp,
                  t.profile.top_ramp, t.profile.top_weight, t.profile.base_erosion, t.noise_scale_m, t.noise_vertical_scale,
                  t.stratiform ? 1 : 0, t.anvil.spread, t.anvil.base, t.anvil.top, t.anvil.density_ratio);
    key += b;
    if (t.strand_ratio != 1.0) {  // (absent for the types without strands: their earlier keys stay valid)
      std::snprintf(b, sizeof b, " strands %.9g", t.strand_ratio);
      key += b;
    }
    if (t.base_relief != 0.0) {  // (absent for the types with a flat base: their earlier keys stay valid)
      std::snprintf(b, sizeof b, " relief %.9g", t.base_relief);
      key += b;
    }
  }
  return key;
}

// 64-bit FNV-1a of the key, as 16 hex digits (the cache file's name; the full key is stored
// in the file and compared on reading, so a collision only costs a re-render).
inline std::string key_hash(const std::string& key) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : key) { h ^= c; h *= 1099511628211ull; }
  char b[17];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}

}  // namespace cloudsvc::bench
