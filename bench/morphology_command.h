// `cloudbench --morphology`: how the weather presets' clouds measure against observations
// (issue 15). Every preset is rendered looking straight down from --altitude (default 20 km)
// at three places (tropical Atlantic, Zurich, off Sydney; local late morning, square frames
// of --size px, 60° field of view), held still for 17 frames (the default preset visits
// every pixel in 16), and the metrics of renderer/reference/cloud_morphology.h are taken
// on the last frame:
//  - perimeter-area dimension D of the clouds (opacity > 0.5, 4-connected, >= 10 px, not
//    touching the border), fitted over the clouds of all three views; observed 1.35
//    (Lovejoy 1982);
//  - cloud-size exponent b of N(>A) ∝ A^-b over the same clouds;
//  - the strongest periodic autocorrelation peak of opacity over its ring's median (radii
//    1/16 to 1/2 of the width), the largest of the three views; <= 0.1 for a field that
//    does not repeat;
//  - the slope of the luminance energy spectrum along rows over wavelengths 0.5-8 km at
//    the lowest layer's middle (pixel size there from the camera's height above it),
//    mean of the views; observed -5/3 for stratocumulus (Cahalan & Snider 1989);
//  - for cumulonimbus layers, from the CPU reference's density field under the three
//    places (60 x 60 km at 250 m): the largest cloud fraction in the layer's top fifth over
//    that at mid-height (reference::anvil_ratio; >= 2 with anvils).
// Writes OUT/morphology.md (the table), OUT/morphology.csv and OUT/morphology_sheet.png (a
// contact sheet: one row per preset, one column per place, and a last column seen from
// 1 km at Zurich looking east 3° above the horizon) and prints the table.
//
// --reference-size N adds the Zurich view rendered by the CPU reference and by the GPU at
// N x N, with both images' cloud fraction, cloud count, D and autocorrelation peak
// (OUT/morphology_reference.csv and a second table).
//
//   build/bin/cloudbench --morphology [--size 192] [--altitude 20000] [--quality default]
//                        [--presets a,b,...] [--reference-size 0] [--out bench-out]
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "geodesy/utc_time.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/image_output.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/cloud_morphology.h"
#include "renderer/reference/reference_inputs.h"
#include "renderer/reference/reference_renderer.h"
#include "weather/presets.h"

namespace cloudsvc::morphology_command {

struct Place {
  const char* name;
  double lat_deg, lon_deg;
  const char* time_utc;  // local late morning
};
inline const Place kPlaces[] = {{"tropical Atlantic", 5.0, -30.0, "2026-03-20T12:00:00Z"},
                                {"Zurich", 47.4, 8.5, "2026-06-21T10:00:00Z"},
                                {"off Sydney", -34.0, 152.0, "2026-12-21T01:00:00Z"}};

struct Result {
  std::string preset;
  reference::PowerLawFit dimension, sizes;
  double autocorrelation_peak = 0.0, spectrum_slope = 0.0;
  int clouds = 0, spectrum_views = 0;
  double cloud_fraction = 0.0;  // mean over the views of the fraction of pixels with opacity > 0.5
  double anvil_top = 0.0, anvil_mid = 0.0;  // cumulonimbus layers: cloud fractions summed over the places
  bool has_cumulonimbus = false;
};

inline std::string fmt(const char* f, double v) {
  if (!std::isfinite(v)) return "–";
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

constexpr int kFrames = 17;              // still frames per view; the last is measured
constexpr double kFov = 60.0;            // degrees, square frames
constexpr double kSideAltitudeM = 1000.0;  // the contact sheet's side views

// The last of kFrames frames of the still view v of weather w (a fresh history).
inline FrameImage still_view(CloudRenderer& renderer, const weather::Weather& w, ViewRequest v, const RenderQuality& q) {
  renderer.set_weather(w);
  v.reset_history = true;
  FrameImage img;
  for (int f = 0; f < kFrames; ++f) {
    v.frame_index = static_cast<std::uint32_t>(f);
    img = renderer.render(v, q);
    v.reset_history = false;
  }
  if (img.stats.nonfinite_pixels) std::fprintf(stderr, "cloudbench --morphology: non-finite pixels\n");
  return img;
}

// Copies img into sheet with its top-left corner at (x0, y0).
inline void paste(FrameImage& sheet, const FrameImage& img, int x0, int y0) {
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 4; ++c)
        sheet.rgba[((static_cast<std::size_t>(y0) + y) * sheet.width + x0 + x) * 4 + c] =
            img.rgba[(static_cast<std::size_t>(y) * img.width + x) * 4 + c];
}

// The image metrics of one frame (for the CPU reference vs GPU comparison).
struct FrameMorphology {
  double cloud_fraction = 0.0, dimension = 0.0, autocorrelation_peak = 0.0;
  int clouds = 0;
};
inline FrameMorphology frame_morphology(const FrameImage& img) {
  const reference::Field opacity = reference::opacity_field(img);
  FrameMorphology m;
  m.cloud_fraction = reference::cloud_fraction(opacity);
  const reference::PowerLawFit d = reference::perimeter_area_dimension(reference::cloud_objects(opacity));
  m.dimension = d.exponent;
  m.clouds = d.n;
  m.autocorrelation_peak = reference::periodic_autocorrelation_peak(opacity, img.width / 16.0, img.width / 2.0);
  return m;
}

// top / mid cloud fraction of the cumulonimbus layers over the places; NaN without one
inline double anvil_of(const Result& r) {
  return r.has_cumulonimbus && r.anvil_mid > 0.0 ? r.anvil_top / r.anvil_mid : std::nan("");
}

inline int run(int argc, char** argv) {
  CLI::App app{"Cloud morphology of the weather presets against observations (cloudbench --morphology)"};
  int size = 192;
  double altitude_m = 20000.0;
  std::string quality = "default", presets_text, out = "bench-out";
  app.add_option("--size", size, "square frame size, px")->check(CLI::Range(64, 512));
  app.add_option("--altitude", altitude_m, "camera altitude above the ellipsoid, m")->check(CLI::Range(5000.0, 100000.0));
  app.add_option("--quality", quality, "quality preset");
  app.add_option("--presets", presets_text, "comma-separated weather presets (default: all)");
  int reference_size = 0;
  app.add_option("--reference-size", reference_size,
                 "also render the Zurich view with the CPU reference and the GPU at this square size and compare "
                 "their metrics (0: not)")
      ->check(CLI::Range(0, 256));
  bool noise_tiling = false;
  app.add_option("--noise-tiling", noise_tiling,
                 "read the noise through its stochastic tiling (RendererConfig::noise_tiling), GPU and reference");
  app.add_option("--out", out, "output directory");
  CLI11_PARSE(app, argc, argv);
  const auto q = quality_preset(quality);
  if (!q) {
    std::fprintf(stderr, "cloudbench --morphology: unknown or CPU-only quality preset %s\n", quality.c_str());
    return 2;
  }
  std::vector<std::string> presets;
  if (presets_text.empty()) presets = weather::preset_names();
  std::stringstream ss(presets_text);
  for (std::string name; std::getline(ss, name, ',');) presets.push_back(name);
  for (const std::string& p : presets)
    if (!weather::preset(p)) {
      std::fprintf(stderr, "cloudbench --morphology: unknown weather preset %s\n", p.c_str());
      return 2;
    }
  const std::filesystem::path dir = out;
  std::filesystem::create_directories(dir);
  // anvil ratio of cumulonimbus layers: the density field under each place on a grid of
  // 60 x 60 km at 250 m; cloud = extinction above 5 % of the layer's largest
  constexpr double kAnvilHalfWidthM = 30000.0, kAnvilSpacingM = 250.0;
  const int n_places = static_cast<int>(std::size(kPlaces));

  gl::EglContext context;
  RendererConfig config;
  config.noise_tiling = noise_tiling;
  CloudRenderer renderer(config);
  reference::ReferenceSettings reference_settings;
  reference_settings.noise_tiling = noise_tiling;
  FrameImage sheet;
  sheet.width = size * (n_places + 1);
  sheet.height = size * static_cast<int>(presets.size());
  sheet.rgba.assign(static_cast<std::size_t>(sheet.width) * sheet.height * 4, 0.0f);
  std::vector<Result> results;
  for (std::size_t pi = 0; pi < presets.size(); ++pi) {
    const weather::Weather w = *weather::preset(presets[pi]);
    Result res;
    res.preset = presets[pi];
    std::vector<reference::CloudObject> clouds;
    double slope_sum = 0.0;
    for (int k = 0; k < n_places; ++k) {
      const Place& pl = kPlaces[k];
      ViewRequest v;
      v.position = {pl.lat_deg, pl.lon_deg, altitude_m};
      v.attitude = {0.0, -90.0, 0.0};
      v.unix_time_s = *geo::parse_utc_iso8601(pl.time_utc);
      v.width = v.height = size;
      v.fov_deg = kFov;
      const FrameImage img = still_view(renderer, w, v, *q);
      const reference::Field opacity = reference::opacity_field(img);
      for (const reference::CloudObject& c : reference::cloud_objects(opacity)) clouds.push_back(c);
      res.cloud_fraction += reference::cloud_fraction(opacity) / n_places;
      res.autocorrelation_peak =
          std::max(res.autocorrelation_peak, reference::periodic_autocorrelation_peak(opacity, size / 16.0, size / 2.0));
      if (!w.layers.empty()) {
        const double h_above = altitude_m - 0.5 * (w.layers.front().base_m + w.layers.front().top_m);
        const double pixel_m = 2.0 * h_above * std::tan(0.5 * kFov * std::numbers::pi / 180.0) / size;
        const reference::PowerLawFit s =
            reference::row_energy_spectrum_slope(reference::luminance_field(img), pixel_m, 500.0, 8000.0);
        if (std::isfinite(s.exponent)) {
          slope_sum += s.exponent;
          ++res.spectrum_views;
        }
      }
      const bool has_cb = std::any_of(w.layers.begin(), w.layers.end(), [](const weather::CloudLayer& l) {
        return l.type == weather::CloudType::Cumulonimbus;
      });
      const reference::ReferenceScene scene = has_cb ? reference::make_reference_scene(v, w) : reference::ReferenceScene{};
      const auto inputs = has_cb ? reference::reference_inputs(reference::InputConfig{}, w.map_seed) : nullptr;
      for (std::size_t li = 0; li < w.layers.size() && has_cb; ++li) {
        if (w.layers[li].type != weather::CloudType::Cumulonimbus) continue;
        const reference::CloudField field(scene, *inputs, true, false, noise_tiling);
        const reference::ReferenceLayer& L = scene.layers[li];
        const reference::AnvilRatio a = reference::anvil_ratio(scene, field, static_cast<int>(li), kAnvilHalfWidthM,
                                                               kAnvilSpacingM, 0.05 * L.density_scale * L.sigma_max_per_m);
        res.anvil_top += a.top_fraction;
        res.anvil_mid += a.mid_fraction;
        res.has_cumulonimbus = true;
      }
      paste(sheet, img, k * size, static_cast<int>(pi) * size);
    }
    {  // the side view: from 1 km at the first place with clouds in the sheet, 3° above the horizon
      ViewRequest v;
      v.position = {kPlaces[1].lat_deg, kPlaces[1].lon_deg, kSideAltitudeM};
      v.attitude = {90.0, 3.0, 0.0};
      v.unix_time_s = *geo::parse_utc_iso8601(kPlaces[1].time_utc);
      v.width = v.height = size;
      v.fov_deg = kFov;
      paste(sheet, still_view(renderer, w, v, *q), n_places * size, static_cast<int>(pi) * size);
    }
    res.dimension = reference::perimeter_area_dimension(clouds);
    res.sizes = reference::cloud_size_exponent(clouds);
    res.clouds = res.dimension.n;
    res.spectrum_slope = res.spectrum_views ? slope_sum / res.spectrum_views : std::nan("");
    results.push_back(res);
    std::printf("%-22s D %s (%d clouds), b %s, autocorrelation peak %.3f, spectrum slope %s, anvil ratio %s\n",
                res.preset.c_str(), fmt("%.3f", res.dimension.exponent).c_str(), res.clouds,
                fmt("%.2f", res.sizes.exponent).c_str(), res.autocorrelation_peak, fmt("%.2f", res.spectrum_slope).c_str(),
                fmt("%.2f", anvil_of(res)).c_str());
    std::fflush(stdout);
  }

  std::ostringstream md;
  md << "Command: `cloudbench --morphology --size " << size << " --altitude " << altitude_m << " --quality " << quality
     << (noise_tiling ? " --noise-tiling on" : "") << "`; nadir views at " << n_places << " places, the last of " << kFrames << " frames.\n\n"
     << "| weather preset | cloud px % (opacity > 0.5) | clouds (>= 10 px, inside) | perimeter-area D (obs. 1.35) | "
        "fit r² | size exponent b | periodic autocorrelation peak (<= 0.1) | spectrum slope 0.5-8 km (obs. -5/3) | "
        "Cb anvil ratio (>= 2) |\n"
     << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  std::ofstream csv(dir / "morphology.csv");
  csv << "preset,cloud_fraction,clouds,dimension,dimension_r2,size_exponent,autocorrelation_peak,spectrum_slope,"
         "anvil_ratio\n";
  for (const Result& r : results) {
    md << "| " << r.preset << " | " << fmt("%.1f", 100.0 * r.cloud_fraction) << " | " << r.clouds << " | "
       << fmt("%.3f", r.dimension.exponent) << " | " << fmt("%.3f", r.dimension.r2) << " | "
       << fmt("%.2f", r.sizes.exponent) << " | " << fmt("%.3f", r.autocorrelation_peak) << " | "
       << fmt("%.2f", r.spectrum_slope) << " | " << fmt("%.2f", anvil_of(r)) << " |\n";
    csv << r.preset << ',' << r.cloud_fraction << ',' << r.clouds << ',' << r.dimension.exponent << ','
        << r.dimension.r2 << ',' << r.sizes.exponent << ',' << r.autocorrelation_peak << ',' << r.spectrum_slope << ','
        << anvil_of(r) << '\n';
  }
  if (reference_size > 0) {
    // the same view on the CPU reference (its own march and light; docs/REFERENCE.md) and
    // the GPU: the clouds should be the same clouds
    md << "\nCPU reference vs GPU (" << quality << "), Zurich from " << altitude_m << " m straight down, "
       << reference_size << " px:\n\n| weather preset | cloud px % reference / GPU | clouds reference / GPU | "
       << "D reference / GPU | periodic autocorrelation peak reference / GPU |\n|---|---:|---:|---:|---:|\n";
    std::ofstream rcsv(dir / "morphology_reference.csv");
    rcsv << "preset,cloud_fraction_reference,cloud_fraction_gpu,clouds_reference,clouds_gpu,dimension_reference,"
            "dimension_gpu,autocorrelation_peak_reference,autocorrelation_peak_gpu\n";
    for (const std::string& name : presets) {
      const weather::Weather w = *weather::preset(name);
      if (w.layers.empty()) continue;
      ViewRequest v;
      v.position = {kPlaces[1].lat_deg, kPlaces[1].lon_deg, altitude_m};
      v.attitude = {0.0, -90.0, 0.0};
      v.unix_time_s = *geo::parse_utc_iso8601(kPlaces[1].time_utc);
      v.width = v.height = reference_size;
      v.fov_deg = kFov;
      const FrameMorphology g = frame_morphology(still_view(renderer, w, v, *q));
      const FrameMorphology r = frame_morphology(reference::render_reference(v, w, reference_settings));
      md << "| " << name << " | " << fmt("%.1f", 100.0 * r.cloud_fraction) << " / " << fmt("%.1f", 100.0 * g.cloud_fraction)
         << " | " << r.clouds << " / " << g.clouds << " | " << fmt("%.3f", r.dimension) << " / " << fmt("%.3f", g.dimension)
         << " | " << fmt("%.3f", r.autocorrelation_peak) << " / " << fmt("%.3f", g.autocorrelation_peak) << " |\n";
      rcsv << name << ',' << r.cloud_fraction << ',' << g.cloud_fraction << ',' << r.clouds << ',' << g.clouds << ','
           << r.dimension << ',' << g.dimension << ',' << r.autocorrelation_peak << ',' << g.autocorrelation_peak << '\n';
      std::printf("%-22s reference vs GPU: cloud %.1f / %.1f %%, D %s / %s, autocorrelation %.3f / %.3f\n", name.c_str(),
                  100.0 * r.cloud_fraction, 100.0 * g.cloud_fraction, fmt("%.3f", r.dimension).c_str(),
                  fmt("%.3f", g.dimension).c_str(), r.autocorrelation_peak, g.autocorrelation_peak);
      std::fflush(stdout);
    }
  }
  std::ofstream(dir / "morphology.md") << md.str();
  write_image((dir / "morphology_sheet.png").string(), sheet);
  std::printf("\n%s\ncloudbench --morphology -> %s\n", md.str().c_str(), dir.string().c_str());
  return 0;
}

}  // namespace cloudsvc::morphology_command
