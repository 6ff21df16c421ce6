// The cloud buffer's temporal-reuse uniform block (binding gpu::ubo::TEMPORAL), the C++ side
// of shaders/temporal_uniforms.glsl: same member names, types and std140 offsets
// (tests/gpu_interface_test.cpp checks them). Written by pack_temporal_uniforms
// (renderer/temporal_reprojection.h) only.
#pragma once

#include <glm/glm.hpp>

#include "renderer/gpu_interface.h"

namespace cloudsvc {

// Index of the ground's transform in TemporalUniforms::reproject (0 .. kMaxLayers - 1 are
// the cloud layers).
constexpr int kGroundTransform = gpu::kMaxLayers;

struct TemporalUniforms {
  // current local frame -> previous local frame (m): the cloud field of each layer (camera
  // motion and that layer's wind), then the ground
  glm::mat4 reproject[gpu::kMaxLayers + 1];
  alignas(16) glm::vec3 prev_forward;  // previous camera axes, in the previous local frame
  float prev_tan_half_fov_x;
  alignas(16) glm::vec3 prev_right;
  float prev_tan_half_fov_y;
  alignas(16) glm::vec3 prev_up;
  float history_blend_min;  // least weight of a fresh sample against its history
  alignas(16) glm::ivec2 cloud_buffer_size;  // cloud pixels
  int fresh_stride;   // this frame marches one cloud pixel in stride x stride
  int history_valid;  // 1: the previous buffer is reprojected
  alignas(8) glm::ivec2 fresh_offset;  // of the marched pixels within their stride x stride cell
  int cloud_divisor;        // frame pixels per cloud pixel, per axis
  int neighbourhood_clamp;  // 1: moved history is limited to the range of fresh neighbours
  int camera_still;         // 1: the camera neither moved nor turned since the last frame
  int footprint_sample;     // footprint_sample_index(): 0 the pixel centre, n the n-th jitter point
  float prev_center_tan_x;  // the previous image window's centre (ImageWindow::center_x, center_y)
  float prev_center_tan_y;
};

static_assert(sizeof(TemporalUniforms) == (gpu::kMaxLayers + 1) * 64 + 6 * 16, "std140 layout");

}  // namespace cloudsvc
