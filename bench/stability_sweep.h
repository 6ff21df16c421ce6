// Numerical-stability stress sweep (issue "Accuracy", part 4), shared by
// bench/cloudbench_stability.cpp (full sweep) and tests/stability_sweep_test.cpp (reduced).
// Header only, no gtest. The caller owns a current GL context (gl::EglContext).
//
// Three checks (docs/STABILITY.md):
//  1. frames: every pixel finite and >= 0, stats.nonfinite_pixels == 0, no exception and
//     no GL error, over poses at the poles, the antimeridian, 0..100 km, layer boundaries,
//     all headings, pitch +-90 deg, sun elevation -20..90 deg, every preset;
//  2. smoothness: 1 cm translations and 0.001 deg rotations (same frame_index, so the same
//     jitter) change pixels by less than a noise floor (see SmoothLimits; gated on the
//     image mean and the fraction > 1 %) and per pixel against each pixel's own jitter
//     noise (PixelStats: two twins, then the wide floor of PixelLimits::extra_twins);
//  3. uptime: weather set (wind anchor latched) at T, views at T + 600 s, 1 h and 30 days
//     against the CPU reference with the same anchor, and the GPU's float noise coordinates
//     against double (see check_uptime).
#pragma once

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "geodesy/geodetic.h"
#include "geodesy/solar_position.h"
#include "geodesy/utc_time.h"
#include "renderer/cloud_renderer.h"
#include "renderer/reference/image_metrics.h"
#include "renderer/reference/reference_renderer.h"
#include "renderer/reference/reference_scene.h"
#include "renderer/frame_uniforms_packing.h"
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

// The mean of n single frames of v with frame_index f0 .. f0 + n - 1 (the renderer's
// estimate of the view from n footprint/jitter samples; n = 1: one frame). The first failed
// frame's check is returned.
inline FrameCheck render_mean(CloudRenderer& r, ViewRequest v, std::uint32_t f0, int n, FrameImage* out,
                              const RenderQuality& q) {
  FrameImage sum;
  for (int k = 0; k < n; ++k) {
    v.frame_index = f0 + static_cast<std::uint32_t>(k);
    FrameImage img;
    const FrameCheck c = check_frame(r, v, &img, q);
    if (!c.ok()) return c;
    if (k == 0) {
      sum = std::move(img);
    } else {
      for (size_t i = 0; i < sum.rgba.size(); ++i) sum.rgba[i] += img.rgba[i];
    }
  }
  if (n > 1)
    for (float& x : sum.rgba) x /= static_cast<float>(n);
  if (out) *out = std::move(sum);
  return {};
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

// The per-pixel change of that metric (row-major, one value per pixel); empty if the sizes differ.
inline std::vector<double> pixel_changes(const FrameImage& a, const FrameImage& b) {
  const size_t n = static_cast<size_t>(a.width) * a.height;
  std::vector<double> out;
  if (b.rgba.size() != a.rgba.size() || n == 0) return out;
  double mean[3] = {0, 0, 0};
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) mean[c] += 0.5 * (a.rgba[i * 4 + c] + b.rgba[i * 4 + c]) / static_cast<double>(n);
  out.resize(n);
  for (size_t i = 0; i < n; ++i) {
    double px = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double x = a.rgba[i * 4 + c], y = b.rgba[i * 4 + c];
      const double rel = std::abs(x - y) / (std::max(std::abs(x), std::abs(y)) + 0.01 * mean[c] + 1e-30);
      px = std::max(px, std::isfinite(rel) ? rel : INFINITY);
    }
    out[i] = px;
  }
  return out;
}

inline ImageDiff image_diff(const FrameImage& a, const FrameImage& b, double tau) {
  ImageDiff d;
  const std::vector<double> px = pixel_changes(a, b);
  if (px.empty()) { d.max_rel = d.frac_above = d.mean_rel = INFINITY; return d; }
  size_t above = 0;
  double sum = 0.0;
  for (double c : px) {
    d.max_rel = std::max(d.max_rel, c);
    sum += c;
    above += c > tau ? 1 : 0;
  }
  d.mean_rel = sum / static_cast<double>(px.size());
  d.frac_above = static_cast<double>(above) / static_cast<double>(px.size());
  return d;
}

// Per-pixel view of a step: each pixel's change s against its own jitter noise
// j = max(change to twin i + 1, change to twin i + 2) of that pixel, and for pairs that fail
// that, against the wide floor j_wide (PixelLimits::extra_twins). The per-pixel criterion
// "no pixel changes by more than k j_wide + a" is what a strict reading of "no pixel changes
// by more than the noise floor" asks; the sweep gates on it (bench/stability_command.h).
struct PixelLimits {
  double k = 3.0;           // multiple of the pixel's own jitter-twin change
  double allowance = 0.02;  // absolute allowance (the relative-change metric above: 2 %)
  // Pairs that fail against the two twins are judged again against a wider noise floor:
  // this many more jitter twins of the base pose and as many of the perturbed pose (0 = no
  // second look). Two twins see a pixel's noise only if it is frequent: a thin bright
  // feature inside the pixel footprint, hit by one frame's sample in ten, leaves both twins
  // unchanged (j = 0) while one sample in ten flips. The wider floor is
  // j_wide = max(j, changes of the base to its extra twins, changes of the perturbed render
  // to its own twins): the noise at either end of the step, which is symmetric in the two poses.
  int extra_twins = 8;
};

struct PixelStats {
  double max_ratio = 0.0;       // largest s / j over pixels with j > 0
  double max_criterion = 0.0;   // largest s / (k j + a): > 1 fails the per-pixel criterion
  double worst_s = 0.0, worst_j = 0.0;  // s and j of the pixel that sets max_criterion
  int worst_x = 0, worst_y = 0;
  int pixels_over = 0;          // pixels with s > k j + a
  int changed_without_noise = 0;  // pixels with j == 0 and s > a (e.g. a clear-sky edge)
  // Against the wider floor (PixelLimits::extra_twins; only computed when pixels_over > 0):
  int pixels_over_wide = 0;     // pixels with s > k j_wide + a
  int wide_without_noise = 0;   // of those, pixels with j_wide == 0: deterministic (no jitter reaches them)
  bool ok() const { return pixels_over == 0; }
  bool ok_wide() const { return pixels_over_wide == 0; }
};

inline PixelStats pixel_stats(const std::vector<double>& step, const std::vector<double>& twin1,
                              const std::vector<double>& twin2, int width, const PixelLimits& lim) {
  PixelStats p;
  if (step.empty() || step.size() != twin1.size() || step.size() != twin2.size()) { p.max_criterion = INFINITY; return p; }
  for (size_t i = 0; i < step.size(); ++i) {
    const double s = step[i], j = std::max(twin1[i], twin2[i]);
    if (j > 0.0) p.max_ratio = std::max(p.max_ratio, s / j);
    const double crit = s / (lim.k * j + lim.allowance);
    if (crit > p.max_criterion) {
      p.max_criterion = crit;
      p.worst_s = s;
      p.worst_j = j;
      p.worst_x = static_cast<int>(i % static_cast<size_t>(width));
      p.worst_y = static_cast<int>(i / static_cast<size_t>(width));
    }
    p.pixels_over += crit > 1.0 ? 1 : 0;
    p.changed_without_noise += (j == 0.0 && s > lim.allowance) ? 1 : 0;
  }
  return p;
}

// Pass criterion of one perturbation (same frame_index, so the same jitter). The noise floor
// is what the renderer already shows from frame to frame: the larger of the changes from
// frame_index i to i + 1 and to i + 2 of the same pose (with SmoothLimits::frames_per_image
// n > 1: of the n-frame means from i, i + n and i + 2n; the per-pixel jitter of the march;
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
  // Each image compared is the mean of this many single frames with consecutive frame
  // indices (render_mean): the base and every step from the same indices f .. f + n - 1,
  // the jitter twins from the next blocks of n (f + n .., f + 2n ..). With footprint jitter
  // a single frame is one random point of each pixel, whose frame-to-frame noise at a cloud
  // edge is the whole contrast within the pixel (a floor no step can exceed); the mean of n
  // is the renderer's estimate of the pixel footprint, with a floor ~1/sqrt(n) as wide.
  int frames_per_image = 1;
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
  ImageDiff jitter;  // noise floor: the larger of the twins (next frame-index blocks) vs the base, same pose
  PixelStats pixels; // per-pixel view against each pixel's own jitter (two twins, then the wide floor)
  bool ok = false;   // the gate: smooth_step_ok
};

inline ViewRequest translated(const ViewRequest& v, glm::dvec3 enu_m) {
  const glm::dvec3 x = geo::geodetic_to_ecef(v.position) + geo::enu_to_ecef(v.position.lat_deg, v.position.lon_deg) * enu_m;
  ViewRequest o = v;
  o.position = geo::ecef_to_geodetic(x);
  return o;
}

// a[i] = max(a[i], b[i]) (b may be empty after a failed render: then nothing changes).
inline void max_into(std::vector<double>& a, const std::vector<double>& b) {
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) a[i] = std::max(a[i], b[i]);
}

// Renders the base pose, its two jitter twins and six perturbations; one result per
// perturbation. q: the march (temporal reuse must be off: every render is a single frame).
// only_steps: other perturbations instead of the six (name, view; controls in the tests).
inline std::vector<SmoothResult> check_smoothness(CloudRenderer& r, const ViewRequest& v, const SmoothLimits& lim = {},
                                                  const RenderQuality& q = {}, const PixelLimits& plim = {},
                                                  const std::vector<std::pair<std::string, ViewRequest>>* only_steps = nullptr) {
  FrameImage base, twin1, twin2;
  std::vector<SmoothResult> out;
  const int n = std::max(1, lim.frames_per_image);
  const std::uint32_t f = v.frame_index, block = static_cast<std::uint32_t>(n);
  if (!render_mean(r, v, f, n, &base, q).ok() || !render_mean(r, v, f + block, n, &twin1, q).ok() ||
      !render_mean(r, v, f + 2 * block, n, &twin2, q).ok()) {
    SmoothResult bad;
    bad.what = "base render failed";
    out.push_back(bad);
    return out;
  }
  const ImageDiff jitter = jitter_floor(image_diff(base, twin1, lim.tau), image_diff(base, twin2, lim.tau));
  const std::vector<double> px_twin1 = pixel_changes(base, twin1), px_twin2 = pixel_changes(base, twin2);
  // the base's part of the wide floor (PixelLimits::extra_twins), rendered when a step first needs it
  std::vector<double> base_wide;
  bool base_wide_ok = true;
  const double dr = v.attitude.pitch_deg > 89.0 ? -0.001 : 0.001;  // stay within [-90, 90]
  struct Step { const char* what; ViewRequest v; };
  std::vector<Step> steps = {{"east +1 cm", translated(v, {0.01, 0, 0})},
                             {"north +1 cm", translated(v, {0, 0.01, 0})},
                             {"up +1 cm", translated(v, {0, 0, 0.01})},
                             {"heading +0.001 deg", v}, {"pitch +-0.001 deg", v}, {"roll +0.001 deg", v}};
  steps[3].v.attitude.heading_deg += 0.001;
  steps[4].v.attitude.pitch_deg += dr;
  steps[5].v.attitude.roll_deg += 0.001;
  if (only_steps) {
    steps.clear();
    for (const auto& [what, view] : *only_steps) steps.push_back({what.c_str(), view});
  }
  for (const Step& s : steps) {
    SmoothResult res;
    res.what = s.what;
    res.jitter = jitter;
    FrameImage img;
    if (!render_mean(r, s.v, f, n, &img, q).ok()) { res.what += " (render failed)"; out.push_back(res); continue; }
    res.step = image_diff(base, img, lim.tau);
    res.ok = smooth_step_ok(res.step, jitter, lim);
    const std::vector<double> px_step = pixel_changes(base, img);
    res.pixels = pixel_stats(px_step, px_twin1, px_twin2, v.width, plim);
    if (!res.pixels.ok() && plim.extra_twins > 0) {
      // the wide floor: the base's part (its two twins and extra_twins more) once per pose,
      // then this step's own twins
      if (base_wide.empty()) {
        base_wide.resize(px_step.size());
        for (size_t i = 0; i < base_wide.size(); ++i) base_wide[i] = std::max(px_twin1[i], px_twin2[i]);
        for (int k = 0; k < plim.extra_twins; ++k) {
          FrameImage t;
          base_wide_ok = render_mean(r, v, f + (3 + static_cast<std::uint32_t>(k)) * block, n, &t, q).ok() && base_wide_ok;
          max_into(base_wide, pixel_changes(base, t));
        }
      }
      std::vector<double> j_wide = base_wide;
      bool twins_ok = base_wide_ok;
      for (int k = 0; k < plim.extra_twins; ++k) {
        FrameImage t;
        twins_ok = render_mean(r, s.v, f + (1 + static_cast<std::uint32_t>(k)) * block, n, &t, q).ok() && twins_ok;
        max_into(j_wide, pixel_changes(img, t));
      }
      if (!twins_ok) {  // a failed twin would leave the floor too low or too high: the pair fails
        res.what += " (twin render failed)";
        res.ok = false;
        res.pixels.pixels_over_wide = std::max(res.pixels.pixels_over_wide, 1);
      }
      for (size_t i = 0; i < px_step.size(); ++i) {
        if (px_step[i] <= plim.k * j_wide[i] + plim.allowance) continue;
        ++res.pixels.pixels_over_wide;
        res.pixels.wide_without_noise += j_wide[i] == 0.0 ? 1 : 0;
        if (std::getenv("STAB_VERBOSE")) {
          const float *a = &base.rgba[i * 4], *b = &img.rgba[i * 4];
          std::fprintf(stderr, "over (wide floor) %s pixel (%zu,%zu): s %.3g j %.3g j_wide %.3g, rgba %.4g %.4g %.4g %.3f -> %.4g %.4g %.4g %.3f\n",
                       s.what, i % static_cast<size_t>(v.width), i / static_cast<size_t>(v.width), px_step[i],
                       std::max(px_twin1[i], px_twin2[i]), j_wide[i], a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]);
        }
      }
    }
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

// The service latches the wind anchor once: set_weather, then the first render (at T)
// fixes WindAnchor{position, T}; a service that then runs for 30 days renders with 30 days
// elapsed since that anchor. So: set_weather and render at T, then (no set_weather in
// between) render the same view at T + e for a baseline group e = 600, 1200, 1800 s, a
// control e = 1 h and a long group e = 30 d, 30 d + 600 s, 30 d + 1200 s, and compare each
// GPU frame with what it should be:
//  (a) image: the CPU reference (double precision, independent code: reference::
//      render_reference with the same anchor and time). The GPU frame is the mean of
//      `gpu_frames` single frames (frame_index 0, 1, ...: the jitter averaged). PSNR uses
//      one peak for every e (the first baseline reference's), so the cases are comparable.
//      The clouds in view differ from one e to the next, and GPU-vs-reference PSNR depends
//      on what is in view (single cases spread by 4-5 dB at 32x18), hence groups: passes
//      when mean PSNR(long) >= mean PSNR(baseline) - psnr_margin_db and every long or
//      control case >= min PSNR(baseline) - psnr_margin_db. A drift that is wrong after
//      30 days (e.g. elapsed time wrapped modulo a day) costs ~20 dB.
//  (b) uniforms: the noise coordinates the GPU computes in float from the uniforms it gets
//      at T + e (p_field = noise_rotation * p; coord = p_field / period + offset, as in
//      shaders/cloud_density.glsl, emulated in float here) against the same coordinate in
//      double from the reference's own field rotation (reference::field_rotation) at probe
//      points p up to 300 km from the camera; error in metres modulo the noise period.
//      Passes when every error <= coord_tol_m + coord_tol_rel * |p| (float rounding: a few
//      cm at 300 km), at every e. Sub-metre precision losses (an unwrapped float angle or
//      offset) change no 32x18 image measurably but fail this by 30-200x.
struct UptimeLimits {
  double psnr_margin_db = 4.0;
  double coord_tol_m = 0.01;
  double coord_tol_rel = 3e-7;
  int gpu_frames = 8;
  int group_size = 3;            // cases per group, spaced by group_spacing_s
  double group_spacing_s = 600.0;
  double control_s = 3600.0;
  double long_s = 30.0 * kDay;
};

struct UptimeCase {
  int group = 0;                   // 0 baseline, 1 control, 2 long
  double elapsed_s = 0.0;
  double psnr_db = 0.0;            // GPU mean frame vs reference, peak = first baseline reference's peak
  double relative_rmse = 0.0;
  double ref_cloud_fraction = 0.0; // reference pixels with opacity > 0.01
  double sun_elevation_deg = 0.0;
  double coord_err_m = 0.0;        // largest noise-coordinate error over probes, layers, base and detail
  double coord_err_ratio = 0.0;    // largest error / (coord_tol_m + coord_tol_rel |p|)
  double ref_s = 0.0;              // wall time of the reference render
};

struct UptimeResult {
  std::vector<UptimeCase> cases;   // baseline group, control, long group
  double mean_psnr[3] = {0, 0, 0}; // per group
  double min_psnr[3] = {0, 0, 0};
  double max_coord_ratio = 0.0;
  double max_coord_err_m = 0.0;
  double drift_mean_rel = 0.0;     // control: the reference at 1 h vs at 600 s (the field does move)
  bool image_ok = false, coords_ok = false;
  bool ok() const { return image_ok && coords_ok; }
};

// Mean of n single GPU frames of the view with frame_index 0 .. n-1 (jitter averaged).
inline FrameImage mean_gpu_frame(CloudRenderer& r, ViewRequest v, int n, const RenderQuality& q) {
  FrameImage sum;
  for (int k = 0; k < n; ++k) {
    v.frame_index = static_cast<std::uint32_t>(k);
    FrameImage img = r.render(v, q);
    if (k == 0) { sum = img; continue; }
    for (size_t i = 0; i < sum.rgba.size(); ++i) sum.rgba[i] += img.rgba[i];
  }
  for (float& x : sum.rgba) x /= static_cast<float>(std::max(n, 1));
  return sum;
}

// Largest error of the GPU's float noise coordinates (from the uniforms) against double,
// in metres; ratio: against coord_tol_m + coord_tol_rel |p|.
inline void noise_coordinate_error(const ViewRequest& view, const weather::Weather& wx, const WindAnchor& anchor,
                                   const UptimeLimits& lim, double* err_m, double* ratio) {
  *err_m = 0.0;
  *ratio = 0.0;
  const FrameUniforms u = pack_frame_uniforms(make_frame_context(view, wx, anchor), {}, {});
  const glm::dvec3 cam = geo::geodetic_to_ecef(view.position);
  const glm::dmat3 E = geo::enu_to_ecef(view.position.lat_deg, view.position.lon_deg);
  const int n = std::min<int>(static_cast<int>(wx.layers.size()), gpu::kMaxLayers);
  for (int l = 0; l < n; ++l) {
    const weather::CloudLayer& layer = wx.layers[static_cast<size_t>(l)];
    const weather::CloudTypeTraits& tr = weather::cloud_type_traits(layer.type);
    const CloudLayerGpu& g = u.layers[l];
    const glm::dmat3 rot = reference::field_rotation(layer.wind, anchor, view.unix_time_s);
    // Noise space as make_frame_context defines it (altitude stretched by k at the camera);
    // probes are taken as already stretched (p_stretched = p), which both sides share.
    const glm::dvec3 cam_field = rot * (cam + (tr.noise_vertical_scale - 1.0) * view.position.alt_m * E[2]);
    const glm::mat3 m = glm::mat3(g.noise_rotation);
    for (double dist : {100.0, 2000.0, 20000.0, 100000.0, 300000.0})
      for (double az = 0.0; az < 360.0; az += 45.0)
        for (double el : {-10.0, 0.0, 2.0, 10.0, 45.0, 90.0}) {
          const double a = az * M_PI / 180.0, e = el * M_PI / 180.0;
          const glm::dvec3 p = dist * glm::dvec3(std::cos(e) * std::sin(a), std::cos(e) * std::cos(a), std::sin(e));
          const glm::vec3 pf = m * glm::vec3(p);  // float, as on the GPU
          const glm::dvec3 field = cam_field + rot * (E * p);
          for (int which = 0; which < 2; ++which) {
            const double period = which == 0 ? tr.noise_scale_m : tr.noise_scale_m / 8.0;
            const float inv = which == 0 ? g.base_noise_frequency : g.detail_noise_frequency;
            const glm::vec3 off = which == 0 ? g.base_noise_offset : g.detail_noise_offset;
            const glm::vec3 coord = pf * inv + off;
            glm::dvec3 d = glm::dvec3(coord) - field / period;
            for (int c = 0; c < 3; ++c) d[c] -= std::round(d[c]);
            const double err = glm::length(d) * period;
            *err_m = std::max(*err_m, err);
            *ratio = std::max(*ratio, err / (lim.coord_tol_m + lim.coord_tol_rel * dist));
          }
        }
  }
}

// view: the pose and T (view.unix_time_s). q: the GPU march.
inline UptimeResult check_uptime(CloudRenderer& r, const weather::Weather& wx, const ViewRequest& view,
                                 const UptimeLimits& lim = {}, const RenderQuality& q = {},
                                 const reference::ReferenceSettings& rs = {}) {
  UptimeResult u;
  const double T = view.unix_time_s;
  r.set_weather(wx);  // weather set at T: the next render latches the anchor
  r.render(view, q);
  const WindAnchor anchor{view.position, T};
  std::vector<std::pair<int, double>> schedule;
  for (int k = 0; k < lim.group_size; ++k) schedule.push_back({0, (k + 1) * lim.group_spacing_s});
  schedule.push_back({1, lim.control_s});
  for (int k = 0; k < lim.group_size; ++k) schedule.push_back({2, lim.long_s + k * lim.group_spacing_s});
  std::vector<FrameImage> refs;
  double peak = 0.0;
  for (const auto& [group, e] : schedule) {
    ViewRequest v = view;
    v.unix_time_s = T + e;
    UptimeCase c;
    c.group = group;
    c.elapsed_s = e;
    const FrameImage gpu = mean_gpu_frame(r, v, lim.gpu_frames, q);
    FrameImage ref = reference::render_reference(v, wx, rs, &anchor);
    c.ref_s = ref.stats.render_ms / 1000.0;
    c.sun_elevation_deg = ref.stats.sun_elevation_deg;
    c.ref_cloud_fraction = static_cast<double>(ref.stats.cloud_pixels) / (static_cast<double>(v.width) * v.height);
    if (refs.empty()) peak = reference::compare_images(gpu, ref).peak;
    const reference::ImageDifference d = reference::compare_images(gpu, ref, peak);
    c.psnr_db = d.psnr_db;
    c.relative_rmse = d.relative_rmse;
    noise_coordinate_error(v, wx, anchor, lim, &c.coord_err_m, &c.coord_err_ratio);
    u.max_coord_ratio = std::max(u.max_coord_ratio, c.coord_err_ratio);
    u.max_coord_err_m = std::max(u.max_coord_err_m, c.coord_err_m);
    u.cases.push_back(c);
    if (group == 0 && refs.empty()) refs.push_back(ref);
    if (group == 1) refs.push_back(std::move(ref));
  }
  for (int g = 0; g < 3; ++g) {
    int n = 0;
    u.min_psnr[g] = INFINITY;
    for (const UptimeCase& c : u.cases)
      if (c.group == g) { u.mean_psnr[g] += c.psnr_db; u.min_psnr[g] = std::min(u.min_psnr[g], c.psnr_db); ++n; }
    u.mean_psnr[g] = n ? u.mean_psnr[g] / n : NAN;
  }
  if (refs.size() >= 2) u.drift_mean_rel = image_diff(refs[0], refs[1], 0.01).mean_rel;
  u.image_ok = std::isfinite(u.mean_psnr[0]) && std::isfinite(u.mean_psnr[2]) &&
               u.mean_psnr[2] >= u.mean_psnr[0] - lim.psnr_margin_db;
  for (const UptimeCase& c : u.cases)
    if (c.group != 0) u.image_ok = u.image_ok && std::isfinite(c.psnr_db) && c.psnr_db >= u.min_psnr[0] - lim.psnr_margin_db;
  u.coords_ok = u.max_coord_ratio <= 1.0;
  return u;
}

}  // namespace cloudsvc::stab
