// The CPU reference images of the benchmarks (cloudbench and its --views mode), cached as
// full-float EXR files (rgba as render_reference writes it; attributes: the render's wall
// time in s and its density evaluations per pixel): a reference takes seconds to minutes
// on 2 cores (docs/REFERENCE.md), so each is rendered once per view, size and sampling.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "renderer/api/frame_image.h"
#include "renderer/api/view_request.h"
#include "renderer/reference/reference_renderer.h"
#include "weather/cloud_layer.h"

namespace cloudsvc::bench {

struct CachedReference {
  FrameImage img;
  double seconds = 0.0;   // time of the reference render (from the file if cached)
  double evals_px = 0.0;  // its density evaluations per pixel
  bool cached = false;    // read from the file
};

inline bool read_reference_exr(const std::filesystem::path& p, CachedReference& r) {
  OIIO::ImageBuf buf(p.string());
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT) || buf.nchannels() != 4) return false;
  const OIIO::ImageSpec& s = buf.spec();
  r.img.width = s.width;
  r.img.height = s.height;
  r.img.rgba.resize(static_cast<size_t>(s.width) * s.height * 4);
  buf.get_pixels(OIIO::ROI(0, s.width, 0, s.height, 0, 1, 0, 4), OIIO::TypeDesc::FLOAT, r.img.rgba.data());
  r.seconds = s.get_float_attribute("cloudbench:reference_s", 0.0f);
  r.evals_px = s.get_float_attribute("cloudbench:evals_per_px", 0.0f);
  r.cached = true;
  return true;
}

inline void write_reference_exr(const std::filesystem::path& p, const CachedReference& r) {
  OIIO::ImageSpec spec(r.img.width, r.img.height, 4, OIIO::TypeDesc::FLOAT);  // full float: it is the truth
  spec.attribute("cloudbench:reference_s", static_cast<float>(r.seconds));
  spec.attribute("cloudbench:evals_per_px", static_cast<float>(r.evals_px));
  OIIO::ImageBuf buf(spec, const_cast<float*>(r.img.rgba.data()));
  if (!buf.write(p.string())) std::fprintf(stderr, "cloudbench: cannot write %s\n", p.string().c_str());
}

// The reference of view v in weather w: read from file when it holds an image of v's size,
// else rendered with settings (wind_anchor as render_reference takes it) and written there.
inline CachedReference cached_reference(const std::filesystem::path& file, const ViewRequest& v,
                                        const weather::Weather& w, const reference::ReferenceSettings& settings,
                                        const WindAnchor* wind_anchor = nullptr) {
  CachedReference r;
  if (std::filesystem::exists(file) && read_reference_exr(file, r) && r.img.width == v.width &&
      r.img.height == v.height)
    return r;
  std::filesystem::create_directories(file.parent_path());
  const auto t0 = std::chrono::steady_clock::now();
  r = CachedReference{};
  r.img = reference::render_reference(v, w, settings, wind_anchor);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.evals_px = r.img.stats.density_evals_per_pixel;
  write_reference_exr(file, r);
  return r;
}

}  // namespace cloudsvc::bench
