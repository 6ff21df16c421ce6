// Ring means of an image around the antisolar point, and the angles of their maxima: how
// tests find the glory's first ring and the fogbow in a rendered image.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

#include "renderer/api/frame_image.h"
#include "renderer/model/mie_phase_table.h"
#include "tests/phase_maxima.h"
#include "renderer/reference/reference_scene.h"

namespace cloudsvc::test {

// Mean rgb of the pixels whose ray is [k, k + 1) * bin_deg from the antisolar direction
// (the camera rays and the sun of the reference's scene, which the GPU shares).
struct AntisolarProfile {
  double bin_deg = 0.1;
  std::vector<glm::dvec3> mean;
  std::vector<int> count;
  double angle_deg(double k) const { return (k + 0.5) * bin_deg; }
};

inline AntisolarProfile antisolar_profile(const FrameImage& img, const reference::ReferenceScene& scene, double bin_deg,
                                          double max_deg) {
  AntisolarProfile p;
  p.bin_deg = bin_deg;
  const std::size_t bins = static_cast<std::size_t>(std::ceil(max_deg / bin_deg));
  p.mean.assign(bins, glm::dvec3(0.0));
  p.count.assign(bins, 0);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const glm::dvec3 ray = scene.camera.ray_at(x + 0.5, y + 0.5);
      const double a = model::angle_between(ray, -scene.sun_local) * 180.0 / M_PI;
      const std::size_t k = static_cast<std::size_t>(a / bin_deg);
      if (k >= bins) continue;
      const float* px = &img.rgba[4 * (static_cast<std::size_t>(y) * img.width + x)];
      p.mean[k] += glm::dvec3(px[0], px[1], px[2]);
      ++p.count[k];
    }
  for (std::size_t k = 0; k < bins; ++k)
    if (p.count[k] > 0) p.mean[k] /= p.count[k];
  return p;
}

// Angle from the antisolar point (deg) of the profile's maximum of channel c within
// [from_deg, to_deg]; -1 if none inside.
inline double profile_maximum_deg(const AntisolarProfile& p, int c, double from_deg, double to_deg) {
  const int lo = static_cast<int>(from_deg / p.bin_deg), hi = std::min<int>(static_cast<int>(to_deg / p.bin_deg), static_cast<int>(p.mean.size()) - 1);
  const double k = parabolic_maximum([&](int i) { return p.mean[static_cast<std::size_t>(i)][c]; }, lo, hi);
  return k < 0.0 ? -1.0 : p.angle_deg(k);
}

}  // namespace cloudsvc::test
