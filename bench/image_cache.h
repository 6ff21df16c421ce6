// cloudbench's cache of slow CPU renders (the model reference and the path-traced truth),
// as full-float EXR files keyed by the whole scene (bench_scenes.h reference_key plus the
// renderer's settings): a file is used only if it holds the same key, else the image is
// rendered (on all cores) and written. Header-only: every bench/*.cpp is an executable.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <cstdint>
#include <string>
#include <vector>

#include "bench/bench_scenes.h"
#include "renderer/reference/reference_renderer.h"
#include "renderer/truth/truth_renderer.h"

namespace cloudsvc::bench {

// A file-name-safe form of a scene name.
inline std::string slug(const std::string& s) {
  std::string r;
  for (char c : s) r += (std::isalnum(static_cast<unsigned char>(c)) != 0) ? c : '_';
  return r;
}

struct CachedImage {
  FrameImage img;      // rgba; std_error too for the truth
  std::vector<std::uint8_t> incomplete;  // the truth's incomplete pixels (TruthImage::incomplete)
  double seconds = 0;  // time of the render (from the cache if cached)
  double evals_px = 0;
  std::string key;
  bool cached = false;
};

inline bool read_cached(const std::filesystem::path& p, CachedImage& r) {
  OIIO::ImageBuf buf(p.string());
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT) || (buf.nchannels() != 4 && buf.nchannels() != 8)) return false;
  const OIIO::ImageSpec& s = buf.spec();
  const int channels = buf.nchannels();
  std::vector<float> px(static_cast<size_t>(s.width) * s.height * channels);
  buf.get_pixels(OIIO::ROI(0, s.width, 0, s.height, 0, 1, 0, channels), OIIO::TypeDesc::FLOAT, px.data());
  r.img.width = s.width;
  r.img.height = s.height;
  const size_t n = static_cast<size_t>(s.width) * s.height;
  r.img.rgba.resize(n * 4);
  if (channels == 8) {
    r.img.std_error.resize(n * 3);
    r.incomplete.resize(n);
  }
  for (size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 4; ++c) r.img.rgba[i * 4 + c] = px[i * channels + c];
    if (channels == 8) {
      for (int c = 0; c < 3; ++c) r.img.std_error[i * 3 + c] = px[i * channels + 4 + c];
      r.incomplete[i] = px[i * channels + 7] > 0.5f ? 1 : 0;
    }
  }
  r.seconds = s.get_float_attribute("cloudbench:reference_s", 0.0f);
  r.evals_px = s.get_float_attribute("cloudbench:evals_per_px", 0.0f);
  r.key = s.get_string_attribute("cloudbench:scene_key");
  r.cached = true;
  return true;
}

inline void write_cached(const std::filesystem::path& p, const CachedImage& r) {
  const bool truth = !r.img.std_error.empty();  // rgba, se.rgb, incomplete
  const int channels = truth ? 8 : 4;
  const size_t n = static_cast<size_t>(r.img.width) * r.img.height;
  std::vector<float> px(n * channels);
  for (size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 4; ++c) px[i * channels + c] = r.img.rgba[i * 4 + c];
    if (truth) {
      for (int c = 0; c < 3; ++c) px[i * channels + 4 + c] = r.img.std_error[i * 3 + c];
      px[i * channels + 7] = i < r.incomplete.size() && r.incomplete[i] ? 1.0f : 0.0f;
    }
  }
  OIIO::ImageSpec spec(r.img.width, r.img.height, channels, OIIO::TypeDesc::FLOAT);  // full float: it is the truth
  spec.attribute("cloudbench:reference_s", static_cast<float>(r.seconds));
  spec.attribute("cloudbench:evals_per_px", static_cast<float>(r.evals_px));
  spec.attribute("cloudbench:scene_key", r.key);
  OIIO::ImageBuf buf(spec, px.data());
  if (!buf.write(p.string())) std::fprintf(stderr, "cloudbench: cannot write %s\n", p.string().c_str());
}

// The cached image of `file` if it holds `key`, else render() (returning a CachedImage with
// img and, for the truth, incomplete), timed, written to `file`.
template <class Render>
CachedImage cached_render(const std::filesystem::path& file, const std::string& key, int w, int h,
                          const Render& render) {
  std::filesystem::create_directories(file.parent_path());
  CachedImage r;
  if (std::filesystem::exists(file) && read_cached(file, r) && r.img.width == w && r.img.height == h && r.key == key)
    return r;
  const auto t0 = std::chrono::steady_clock::now();
  r = render();
  r.key = key;
  r.cached = false;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.evals_px = r.img.stats.density_evals_per_pixel;
  write_cached(file, r);
  return r;
}

// The scene's CPU reference (ReferenceSettings::pixel_samples = ref_samples) at w x h under
// dir: <scene>_<W>x<H>[_ss<N>]_<key hash>.exr.
// column_depths: ReferenceSettings::column_depths (the diffuse light's depths from each
// point's own column); sun_slab_tilt: ReferenceSettings::sun_slab_tilt.
inline CachedImage reference_image(const BenchScene& s, const std::filesystem::path& dir, int w, int h,
                                   int ref_samples, bool column_depths = false, bool sun_slab_tilt = false) {
  const std::string key = reference_key(s, ref_samples) + " light model " +
                          std::to_string(reference::kLightModelRevision) + (column_depths ? " column depths" : "") +
                          (sun_slab_tilt ? " sun slab tilt" : "");
  const std::string samples = ref_samples > 1 ? "_ss" + std::to_string(ref_samples) : "";
  const std::filesystem::path file =
      dir / (slug(s.name) + "_" + std::to_string(w) + "x" + std::to_string(h) + samples + "_" + key_hash(key) + ".exr");
  return cached_render(file, key, w, h, [&] {
    reference::ReferenceSettings settings;
    settings.pixel_samples = ref_samples;
    settings.column_depths = column_depths;
    settings.sun_slab_tilt = sun_slab_tilt;
    CachedImage c;
    c.img = reference::render_reference(s.view, s.weather, settings);
    return c;
  });
}

// The scene's path-traced truth (spp paths per pixel from `seed`, at most max_collisions
// tentative collisions per path: TruthImage::incomplete) at w x h under dir:
// <scene>_<W>x<H>_spp<N>_<key hash>.exr, with the standard error and the incomplete pixels.
inline CachedImage truth_image(const BenchScene& s, const std::filesystem::path& dir, int w, int h, int spp,
                               std::uint64_t max_collisions, std::uint64_t seed = 1) {
  const truth::TracerSettings tracer;  // the estimator's defaults and revision are part of the key
  const std::string key = reference_key(s, 1) + " truth spp " + std::to_string(spp) + " cap " +
                          std::to_string(max_collisions) + (seed == 1 ? "" : " seed " + std::to_string(seed)) +
                          " estimator " + std::to_string(truth::kEstimatorRevision) + " guide " +
                          std::to_string(tracer.guide_depth) + " cell " + std::to_string(tracer.guide_cell_m);
  const std::filesystem::path file = dir / (slug(s.name) + "_" + std::to_string(w) + "x" + std::to_string(h) + "_spp" +
                                            std::to_string(spp) + "_" + key_hash(key) + ".exr");
  return cached_render(file, key, w, h, [&] {
    truth::TruthSettings settings;
    settings.spp = spp;
    settings.seed = seed;
    settings.tracer.max_collisions = max_collisions;
    truth::TruthImage t = truth::render_truth(s.view, s.weather, settings);
    CachedImage c;
    c.img = std::move(t.image);
    c.incomplete = std::move(t.incomplete);
    return c;
  });
}

}  // namespace cloudsvc::bench
