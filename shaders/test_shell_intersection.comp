#version 450 core
// Test kernel (tests/gpu_shell_precision_test.cpp): evaluates the renderer's float GLSL
// intersect_shell and altitude_of from common.glsl for a buffer of inputs, so the test can
// compare them with the double geo::intersect_shell on the same GPU (llvmpipe) arithmetic.
//   in_geom[i]  = (R, h, H, mu): sphere radius, camera altitude, shell altitude (m), cos(zenith)
//   in_point[i] = (t, dx, dz, 0): a distance along the ray (m) and the ray direction in the
//                 local frame (x horizontal, z up; camera at the origin, centre at -(R+h) z)
//   out_result[i] = (t0, t1, altitude_of(t * d), 0); t0 = t1 = -1 when the ray misses.
#include "common.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = SSBO_TEST_INPUT_A) readonly buffer Geom { vec4 in_geom[]; };
layout(std430, binding = SSBO_TEST_INPUT_B) readonly buffer Point { vec4 in_point[]; };
layout(std430, binding = SSBO_TEST_OUTPUT) writeonly buffer Result { vec4 out_result[]; };
uniform uint u_count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  vec4 g = in_geom[i];
  vec4 q = in_point[i];
  vec2 t = intersect_shell(g.x, g.y, g.z, g.w);
  vec3 p = q.x * vec3(q.y, 0.0, q.z);
  out_result[i] = vec4(t, altitude_of(p, g.x, g.y), 0.0);
}
