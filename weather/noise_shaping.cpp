#include "weather/noise_shaping.h"

namespace cloudsvc::weather {

glm::dmat3 noise_shaping(const CloudTypeTraits& traits) {
  glm::dmat3 s(1.0);
  s[2][2] = traits.strand_ratio;  // I + (r - 1) z z^T
  return s;
}

}  // namespace cloudsvc::weather
