// Numerical-stability stress sweep (issue "Accuracy", part 4), shared by
// bench/cloudbench_stability.cpp (full sweep) and tests/stability_sweep_test.cpp (reduced).
// Header only, no gtest. The caller owns a current GL context (gl::EglContext).
//
// Three checks (docs/STABILITY.md):
//  1. frames: every pixel finite and >= 0, stats.nonfinite_pixels == 0, no exception and
//     no GL error, over poses at the poles, the antimeridian, 0..100 km, layer boundaries,
//     all headings, pitch +-90 deg, sun elevation -20..90 deg, every preset;
//  2. smoothness: 1 cm translations and 0.001 deg rotations (same frame_index, so the same
//     jitter) change pixels by less than a noise floor (see SmoothLimits);
//  3. uptime: wind anchor at T and view at T + dt equals anchor and view shifted by ~30 days.
#pragma once

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "geodesy/geodetic.h"
#include "geodesy/solar_position.h"
#include "geodesy/utc_time.h"
#include "renderer/cloud_renderer.h"
#include "renderer/scene_setup.h"
#include "weather/presets.h"

namespace cloudsvc::stab {

constexpr double kDay = 86400.0;  // s

// Deterministic generator (splitmix64), so a failing pose index reproduces everywhere.
struct Rng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  template <class T>
  const T& pick(const std::vector<T>& v) { return v[static_cast<size_t>(next() % v.size())]; }
};

// UTC (s) in the day starting at day_start_s when the sun's geometric elevation at (lat, lon)
// crosses target_deg (bisection to 0.01 s); if it never does that day, the time of the
// closest elevation at 10-minute resolution.
inline double utc_for_sun_elevation(double lat, double lon, double day_start_s, double target_deg) {
  auto el = [&](double t) { return geo::solar_position(t, lat, lon).elevation_deg - target_deg; };
  constexpr int kSamples = 144;  // every 10 min
  const double dt = kDay / kSamples;
  double best_t = day_start_s, best = std::abs(el(day_start_s));
  for (int i = 0; i < kSamples; ++i) {
    double a = day_start_s + i * dt, b = a + dt;
    double fa = el(a), fb = el(b);
    if (std::abs(fa) < best) { best = std::abs(fa); best_t = a; }
    if ((fa <= 0.0) != (fb <= 0.0)) {
      for (int k = 0; k < 40 && b - a > 0.01; ++k) {
        const double m = 0.5 * (a + b), fm = el(m);
        if ((fa <= 0.0) == (fm <= 0.0)) { a = m; fa = fm; } else { b = m; }
      }
      return 0.5 * (a + b);
    }
  }
  return best_t;
}

struct Pose {
  std::string preset;
  ViewRequest view;
  double target_sun_deg = 0.0;
};

inline std::string describe(const Pose& p) {
  char buf[320];
  const ViewRequest& v = p.view;
  std::snprintf(buf, sizeof buf, "%s lat %.7f lon %.7f alt %.3f m hdg %.4f pitch %.4f roll %.4f %s (sun target %.1f)",
                p.preset.c_str(), v.position.lat_deg, v.position.lon_deg, v.position.alt_m, v.attitude.heading_deg,
                v.attitude.pitch_deg, v.attitude.roll_deg, geo::format_utc_iso8601(v.unix_time_s).c_str(),
                p.target_sun_deg);
  return buf;
}

// n poses for one preset, mixing special values (poles, antimeridian, equator, layer
// boundaries, pitch +-90) with random ones. Sun target uniform in [-20, 90] deg on a random
// day of 2000..2040 (unreachable targets, e.g. 90 deg at 60 N, give the closest elevation).
inline std::vector<Pose> make_poses(const std::string& preset_name, int n, std::uint64_t seed, int w, int h) {
  const weather::Weather wx = *weather::preset(preset_name);
  Rng rng{seed};
  const std::vector<double> lats = {90.0, -90.0, 0.0, 89.9999, -89.9999, 45.0, -33.9};
  const std::vector<double> lons = {180.0, -180.0, 179.9999, -179.9999, 0.0, -0.0000001};
  std::vector<double> alts = {0.0, 2.0, 100000.0, 99999.99, 12000.0, 1.0e-3};
  for (const auto& l : wx.layers) {  // exactly on each boundary and 1 mm either side
    for (double a : {l.base_m, l.top_m}) { alts.push_back(a); alts.push_back(a - 1e-3); alts.push_back(a + 1e-3); }
    alts.push_back(0.5 * (l.base_m + l.top_m));
  }
  const std::vector<double> pitches = {90.0, -90.0, 0.0, 89.9999, -89.9999, 0.001};
  const std::vector<double> headings = {0.0, 90.0, 180.0, 270.0, 359.9999, -0.0001};
  const double t2000 = *geo::parse_utc_iso8601("2000-01-01T00:00:00Z");
  std::vector<Pose> out;
  out.reserve(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    Pose p;
    p.preset = preset_name;
    ViewRequest& v = p.view;
    v.width = w;
    v.height = h;
    v.fov_deg = rng.uniform() < 0.2 ? rng.uniform(1.0, 120.0) : 60.0;
    v.frame_index = static_cast<std::uint32_t>(rng.next() & 0xffffffu);
    v.position.lat_deg = rng.uniform() < 0.4 ? rng.pick(lats) : std::asin(rng.uniform(-1.0, 1.0)) * 180.0 / M_PI;
    v.position.lon_deg = rng.uniform() < 0.4 ? rng.pick(lons) : rng.uniform(-180.0, 180.0);
    // Altitude: special, or log-uniform 1 m .. 100 km.
    v.position.alt_m = rng.uniform() < 0.5 ? rng.pick(alts) : std::exp(rng.uniform(0.0, std::log(1.0e5)));
    v.attitude.heading_deg = rng.uniform() < 0.3 ? rng.pick(headings) : rng.uniform(0.0, 360.0);
    v.attitude.pitch_deg = rng.uniform() < 0.3 ? rng.pick(pitches) : rng.uniform(-90.0, 90.0);
    v.attitude.roll_deg = rng.uniform() < 0.3 ? rng.uniform(-180.0, 180.0) : 0.0;
    p.target_sun_deg = rng.uniform(-20.0, 90.0);
    const double day = t2000 + std::floor(rng.uniform(0.0, 40.0 * 365.25)) * kDay;
    v.unix_time_s = utc_for_sun_elevation(v.position.lat_deg, v.position.lon_deg, day, p.target_sun_deg);
    out.push_back(p);
  }
  return out;
}

// ---- check 1: one frame ------------------------------------------------------------

struct FrameCheck {
  std::int64_t bad_values = 0;      // NaN, Inf or negative channel values in the image
  std::int64_t nonfinite_stat = 0;  // stats.nonfinite_pixels (shader-side clamps)
  int gl_errors = 0;
  std::string exception;            // what() of anything thrown
  double sun_elevation_deg = 0.0;
  double render_ms = 0.0;
  bool ok() const { return bad_values == 0 && nonfinite_stat == 0 && gl_errors == 0 && exception.empty(); }
};

inline std::int64_t count_bad(const FrameImage& img) {
  std::int64_t bad = 0;
  for (float v : img.rgba) bad += (!std::isfinite(v) || v < 0.0f) ? 1 : 0;
  return bad;
}

inline FrameCheck check_frame(CloudRenderer& r, const ViewRequest& v, FrameImage* keep = nullptr,
                              const RenderQuality& q = {}) {
  FrameCheck c;
  while (glGetError() != GL_NO_ERROR) {}
  try {
    FrameImage img = r.render(v, q);
    c.bad_values = count_bad(img);
    c.nonfinite_stat = img.stats.nonfinite_pixels;
    c.sun_elevation_deg = img.stats.sun_elevation_deg;
    c.render_ms = img.stats.render_ms;
    if (img.rgba.size() != static_cast<size_t>(v.width) * v.height * 4) c.exception = "wrong image size";
    if (keep) *keep = std::move(img);
  } catch (const std::exception& e) {
    c.exception = e.what();
  }
  while (glGetError() != GL_NO_ERROR) ++c.gl_errors;
  return c;
}

// ---- check 2: smoothness -----------------------------------------------------------

// Per-pixel change between two renders: per colour channel |a - b| / (max(a, b) + 0.01 m),
// m = the image's mean radiance in that channel (so near-black pixels, e.g. night ground next
// to a sunlit cloud, cannot produce huge ratios from tiny absolute changes); a pixel's change
// is its largest channel's. Alpha is not compared (it is derived from the same march).
struct ImageDiff {
  double max_rel = 0.0;     // largest change of any pixel
  double frac_above = 0.0;  // fraction of pixels changed by more than `tau`
  double mean_rel = 0.0;    // mean change over the image
};

inline ImageDiff image_diff(const FrameImage& a, const FrameImage& b, double tau) {
  ImageDiff d;
  const size_t n = static_cast<size_t>(a.width) * a.height;
  if (b.rgba.size() != a.rgba.size() || n == 0) { d.max_rel = d.frac_above = d.mean_rel = INFINITY; return d; }
  double mean[3] = {0, 0, 0};
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) mean[c] += 0.5 * (a.rgba[i * 4 + c] + b.rgba[i * 4 + c]) / static_cast<double>(n);
  size_t above = 0;
  double sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    double px = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double x = a.rgba[i * 4 + c], y = b.rgba[i * 4 + c];
      const double rel = std::abs(x - y) / (std::max(std::abs(x), std::abs(y)) + 0.01 * mean[c] + 1e-30);
      px = std::max(px, std::isfinite(rel) ? rel : INFINITY);
    }
    d.max_rel = std::max(d.max_rel, px);
    sum += px;
    above += px > tau ? 1 : 0;
  }
  d.mean_rel = sum / static_cast<double>(n);
  d.frac_above = static_cast<double>(above) / static_cast<double>(n);
  return d;
}

// Pass criterion of one perturbation (same frame_index, so the same jitter). The noise floor
// is what the renderer already shows from frame to frame: the larger of the changes from
// frame_index i to i + 1 and to i + 2 of the same pose (the per-pixel jitter of the march;
// temporal accumulation is meant to average it). One pair alone under-estimates that noise
// about half the time, so a step whose change is itself noise-like failed at random; and
// two such estimates differ by a ratio whose 95th percentile is 1.30 (median 1.07; 110
// poses with clouds, `cloudbench --stability --smooth 200`, 2026-11-22), so a step passes
// within that spread of the floor (noise_spread). A 1 cm / 0.001 deg step must not change the image more than that:
//   mean change <= max(noise_spread * jitter mean change, min_mean) and
//   fraction of pixels changed by > tau <= max(noise_spread * jitter fraction, min_frac).
// The absolute allowances cover views without clouds (no jitter noise): there a step may
// still move a true edge (horizon, sun disk) across a pixel centre (one sample per pixel).
// The largest single-pixel change is reported, not gated, for the same reason.
struct SmoothLimits {
  double tau = 0.01;
  double min_mean = 1e-3;
  double min_frac = 0.02;
  double noise_spread = 1.3;
};

// The noise floor from the changes to two jitter twins (their larger value per measure).
inline ImageDiff jitter_floor(const ImageDiff& j1, const ImageDiff& j2) {
  ImageDiff f;
  f.mean_rel = std::max(j1.mean_rel, j2.mean_rel);
  f.frac_above = std::max(j1.frac_above, j2.frac_above);
  f.max_rel = std::max(j1.max_rel, j2.max_rel);
  return f;
}

// The pass criterion above.
inline bool smooth_step_ok(const ImageDiff& step, const ImageDiff& floor, const SmoothLimits& lim) {
  return step.mean_rel <= std::max(lim.noise_spread * floor.mean_rel, lim.min_mean) &&
         step.frac_above <= std::max(lim.noise_spread * floor.frac_above, lim.min_frac);
}

struct SmoothResult {
  std::string what;  // "east +1 cm", ...
  ImageDiff step;
  ImageDiff jitter;  // noise floor: the larger of frame_index + 1 and + 2 vs frame_index, same pose
  bool ok = false;
};

inline ViewRequest translated(const ViewRequest& v, glm::dvec3 enu_m) {
  const glm::dvec3 x = geo::geodetic_to_ecef(v.position) + geo::enu_to_ecef(v.position.lat_deg, v.position.lon_deg) * enu_m;
  ViewRequest o = v;
  o.position = geo::ecef_to_geodetic(x);
  return o;
}

// Renders the base pose, its two jitter twins and six perturbations; one result per
// perturbation. q: the march (temporal reuse must be off: every render is a single frame).
inline std::vector<SmoothResult> check_smoothness(CloudRenderer& r, const ViewRequest& v, const SmoothLimits& lim = {},
                                                  const RenderQuality& q = {}) {
  FrameImage base, twin1, twin2;
  std::vector<SmoothResult> out;
  ViewRequest vj1 = v, vj2 = v;
  vj1.frame_index = v.frame_index + 1;
  vj2.frame_index = v.frame_index + 2;
  if (!check_frame(r, v, &base, q).ok() || !check_frame(r, vj1, &twin1, q).ok() || !check_frame(r, vj2, &twin2, q).ok()) {
    SmoothResult bad;
    bad.what = "base render failed";
    out.push_back(bad);
    return out;
  }
  const ImageDiff jitter = jitter_floor(image_diff(base, twin1, lim.tau), image_diff(base, twin2, lim.tau));
  const double dr = v.attitude.pitch_deg > 89.0 ? -0.001 : 0.001;  // stay within [-90, 90]
  struct Step { const char* what; ViewRequest v; };
  std::vector<Step> steps = {{"east +1 cm", translated(v, {0.01, 0, 0})},
                             {"north +1 cm", translated(v, {0, 0.01, 0})},
                             {"up +1 cm", translated(v, {0, 0, 0.01})},
                             {"heading +0.001 deg", v}, {"pitch +-0.001 deg", v}, {"roll +0.001 deg", v}};
  steps[3].v.attitude.heading_deg += 0.001;
  steps[4].v.attitude.pitch_deg += dr;
  steps[5].v.attitude.roll_deg += 0.001;
  for (const Step& s : steps) {
    SmoothResult res;
    res.what = s.what;
    res.jitter = jitter;
    FrameImage img;
    if (!check_frame(r, s.v, &img, q).ok()) { res.what += " (render failed)"; out.push_back(res); continue; }
    res.step = image_diff(base, img, lim.tau);
    res.ok = smooth_step_ok(res.step, jitter, lim);
    out.push_back(res);
  }
  return out;
}

// Smoothness poses: anywhere on Earth but |lat| <= 89.9 (at a pole a 1 cm step changes the
// longitude, and with it the meaning of "heading", arbitrarily: a property of the pose
// convention, not of the renderer), altitude 2 m .. 100 km, sun -10..80 deg.
inline std::vector<Pose> make_smooth_poses(const std::vector<std::string>& presets, int n, std::uint64_t seed, int w,
                                           int h) {
  Rng rng{seed};
  const double t2000 = *geo::parse_utc_iso8601("2000-01-01T00:00:00Z");
  std::vector<Pose> out;
  for (int i = 0; i < n; ++i) {
    Pose p;
    p.preset = presets[static_cast<size_t>(i) % presets.size()];
    ViewRequest& v = p.view;
    v.width = w;
    v.height = h;
    v.frame_index = static_cast<std::uint32_t>(i);
    v.position.lat_deg = std::asin(rng.uniform(-1.0, 1.0) * std::sin(89.9 * M_PI / 180.0)) * 180.0 / M_PI;
    v.position.lon_deg = i % 10 == 0 ? 179.99999 : rng.uniform(-180.0, 180.0);
    v.position.alt_m = i % 7 == 0 ? 100000.0 : std::exp(rng.uniform(std::log(2.0), std::log(1.0e5)));
    v.attitude.heading_deg = rng.uniform(0.0, 360.0);
    v.attitude.pitch_deg = rng.uniform(-60.0, 60.0);
    v.attitude.roll_deg = rng.uniform(-30.0, 30.0);
    p.target_sun_deg = rng.uniform(-10.0, 80.0);
    const double day = t2000 + std::floor(rng.uniform(0.0, 40.0 * 365.25)) * kDay;
    v.unix_time_s = utc_for_sun_elevation(v.position.lat_deg, v.position.lon_deg, day, p.target_sun_deg);
    out.push_back(p);
  }
  return out;
}

// ---- check 3: uptime ---------------------------------------------------------------

// The sun moves in 30 days, so the shift S is 30 days plus the few minutes (found by search)
// that put the sun back where it was: T is 15 days before the June solstice, where the
// declination at T and T + 30 d is the same; the equation of time differs by ~6 min.
struct UptimeResult {
  double shift_s = 0.0;             // S, s
  double sun_mismatch_deg = 0.0;    // angle between the sun directions of the two views
  double max_uniform_diff = 0.0;    // largest |difference| of any wind-driven uniform (offsets, rotation)
  ImageDiff image;                  // render(T + dt) vs render(T + S + dt)
  ImageDiff drift;                  // control: render(T + dt) vs render(T + 2 dt): the field does move
};

inline glm::dvec3 sun_enu(double t, double lat, double lon) {
  const geo::SolarPosition sp = geo::solar_position(t, lat, lon);
  const double el = sp.elevation_deg * M_PI / 180.0, az = sp.azimuth_deg * M_PI / 180.0;
  return {std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el)};
}

inline double sun_matching_shift(double t, double lat, double lon) {
  const glm::dvec3 s0 = sun_enu(t, lat, lon);
  double best = 30.0 * kDay, best_d = 1e9;
  for (double s = 30.0 * kDay - 1800.0; s <= 30.0 * kDay + 1800.0; s += 0.5) {
    const double d = glm::length(sun_enu(t + s, lat, lon) - s0);
    if (d < best_d) { best_d = d; best = s; }
  }
  return best;
}

inline UptimeResult check_uptime(CloudRenderer& r, const weather::Weather& wx, ViewRequest view, double dt_s) {
  UptimeResult u;
  const double T = view.unix_time_s;
  const double lat = view.position.lat_deg, lon = view.position.lon_deg;
  u.shift_s = sun_matching_shift(T + dt_s, lat, lon);
  u.sun_mismatch_deg = std::acos(std::min(1.0, glm::dot(sun_enu(T + dt_s, lat, lon), sun_enu(T + u.shift_s + dt_s, lat, lon)))) *
                       180.0 / M_PI;
  auto run = [&](double anchor_t, double view_t) {
    r.set_weather(wx);  // resets the anchor: the next render latches it
    ViewRequest a = view;
    a.unix_time_s = anchor_t;
    r.render(a);
    ViewRequest b = view;
    b.unix_time_s = view_t;
    return r.render(b);
  };
  const FrameImage i1 = run(T, T + dt_s);
  const FrameImage i2 = run(T + u.shift_s, T + u.shift_s + dt_s);
  const FrameImage i3 = run(T, T + 2.0 * dt_s);
  u.image = image_diff(i1, i2, 0.01);
  u.drift = image_diff(i1, i3, 0.01);
  // The same at the uniform level (exact: no sun involved).
  const WindAnchor a1{view.position, T}, a2{view.position, T + u.shift_s};
  ViewRequest v1 = view, v2 = view;
  v1.unix_time_s = T + dt_s;
  v2.unix_time_s = T + u.shift_s + dt_s;
  const FrameUniforms f1 = make_frame_uniforms(v1, wx, {}, {}, &a1), f2 = make_frame_uniforms(v2, wx, {}, {}, &a2);
  for (int l = 0; l < kGpuMaxLayers; ++l) {
    const CloudLayerGpu &g1 = f1.layers[l], &g2 = f2.layers[l];
    for (int k = 0; k < 3; ++k) {
      u.max_uniform_diff = std::max<double>(u.max_uniform_diff, std::abs(g1.base_offset[k] - g2.base_offset[k]));
      u.max_uniform_diff = std::max<double>(u.max_uniform_diff, std::abs(g1.detail_offset[k] - g2.detail_offset[k]));
      for (int j = 0; j < 3; ++j)
        u.max_uniform_diff = std::max<double>(u.max_uniform_diff, std::abs(g1.noise_rotation[j][k] - g2.noise_rotation[j][k]));
    }
  }
  return u;
}

}  // namespace cloudsvc::stab
