// The anisotropy of a layer's shape noise: strands that run east-west (cirrus fibratus
// under the prevailing upper-level westerlies).
//
// The noise is read at S x for the field point x (field frame, m), S = I + (r - 1) z z^T
// with z the Earth's axis (the field frame's z: the wind's solid-body rotation,
// weather/wind_drift.h, turns the world under a fixed S, so the strands drift with the
// cloud): r times finer along z. At latitude phi the horizontal direction it shortens most
// is north-south, by sqrt(1 + (r^2 - 1) cos^2 phi) (r at the equator, 4.1 for r = 6 at
// 47 degrees), and the vertical by sqrt(1 + (r^2 - 1) sin^2 phi); towards the poles the
// strands fade into isotropic cloud. S is linear and fixed, so the strands are one seamless
// map of the world, the same for every camera and wind anchor (a wind-dependent axis would
// move them by kilometres when the anchor moves by metres: S x takes the absolute position).
// The strands do not turn with the layer's wind direction.
#pragma once

#include <glm/glm.hpp>

#include "weather/cloud_layer.h"

namespace cloudsvc::weather {

// S of the header for a layer of type traits `traits` (CloudTypeTraits::strand_ratio): the
// identity for every type with strand_ratio 1.
glm::dmat3 noise_shaping(const CloudTypeTraits& traits);

}  // namespace cloudsvc::weather
