// The ground shadow map's uniform block (binding gpu::ubo::SHADOW_MAP), the C++ side of
// the block in shaders/ground_shadow_map.glsl: same member names, types and std140 offsets
// (tests/gpu_interface_test.cpp checks them). Written by GroundShadowMap::update only.
#pragma once

#include <glm/glm.hpp>

#include "renderer/gpu_interface.h"

namespace cloudsvc {

struct ShadowMapUniforms {
  // current local frame -> the anchor's local frame at build time (m), per layer (the
  // layer's wind drift since the build included)
  glm::mat4 to_anchor[gpu::kMaxLayers];
  float warp_m;         // K of the radial warp u = d / (|d| + K)
  int map_texels;       // N, texels per side
  int map_valid;        // 1: look the ground's cloud shadows up in the map
  int march_per_pixel;  // 1: march them for every ground pixel instead
  int volume_levels;    // light volume: altitude levels per layer
  int volume_texels;    // ... texels per side
  int volume_valid;     // 1: the march reads the light volume instead of a light march
  int column_valid;     // 1: the diffuse light reads its depths from the column volume
  int column_march_steps;  // > 0: ... or marches them from each lit sample in this many steps
  int pad_[3];             // C++ only: std140 rounds the block's size up to 16 bytes
};
static_assert(sizeof(ShadowMapUniforms) == gpu::kMaxLayers * 64 + 48, "std140 layout");

}  // namespace cloudsvc
