#version 450 core
// Test kernel (tests/gpu_cloud_placement_test.cpp): the GPU cloud placement's unit-aspect
// dome top over every level (cloud_placement.glsl) at shell points given relative to the
// frame's centre.
//   in_point[i]  = (x, y, z, floor_m): the point minus the centre C (m, field frame)
//   out_result[i] = (dome top (m), 0, 0, 0)
#include "common.glsl"
#include "cloud_placement.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = SSBO_TEST_INPUT_A) readonly buffer Frame { PlacementFrame in_frame; };
layout(std430, binding = SSBO_TEST_INPUT_B) readonly buffer Point { vec4 in_point[]; };
layout(std430, binding = SSBO_TEST_OUTPUT) writeonly buffer Result { vec4 out_result[]; };
uniform uint u_count;

// one coverage for the whole frame: its per-level values
float placement_acceptance(PlacementFrame pf, int level, vec3 centre) {
  return level < 4 ? pf.acceptance[level] : pf.acceptance_hi[level - 4];
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  out_result[i] = vec4(placement_dome_top(in_frame, in_point[i].xyz, 0, in_frame.levels, in_point[i].w), 0.0, 0.0, 0.0);
}
