#version 450 core
// Test kernel (tests/gpu_cumulus_domes_test.cpp): the dome top a cumulus layer reads
// (cumulus_domes.glsl) at points given relative to the rings' anchor.
//   in_point[i]  = (x, y, z, coverage): the point minus the anchor (m, field frame), the
//                  layer's coverage there
//   out_result[i] = (unit-aspect top (m), 0, 0, 0)
#include "common.glsl"
#include "gradient_noise.glsl"
#include "cumulus_domes.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = SSBO_TEST_INPUT_B) readonly buffer Point { vec4 in_point[]; };
layout(std430, binding = SSBO_TEST_OUTPUT) writeonly buffer Result { vec4 out_result[]; };
uniform uint u_count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  out_result[i] = vec4(dome_top(0, in_point[i].xyz, in_point[i].w), 0.0, 0.0, 0.0);
}
