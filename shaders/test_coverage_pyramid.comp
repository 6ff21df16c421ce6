#version 450 core
// Test kernel (tests/gpu_coverage_pyramid_test.cpp): evaluates the march's float GLSL
// pyramid_max_in_cap (coverage_pyramid.glsl) for a buffer of caps, so the test can compare
// it with the CPU pyramid_max_in_cap (renderer/coverage_pyramid.cpp) on the same pyramid.
//   in_cap[i] = (lat, lon, cap radius, 0), radians; out_max[i] = the bound
#include "common.glsl"
#include "coverage_pyramid.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = SSBO_TEST_INPUT_A) readonly buffer Caps { vec4 in_cap[]; };
layout(std430, binding = SSBO_TEST_OUTPUT) writeonly buffer Result { float out_max[]; };
uniform uint u_count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  vec4 c = in_cap[i];
  out_max[i] = pyramid_max_in_cap(c.x, c.y, c.z);
}
