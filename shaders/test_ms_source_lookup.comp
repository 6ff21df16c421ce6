#version 450 core
// Test kernel (tests/gpu_ms_source_lookup_test.cpp): evaluates ms_source_over_mu and
// ms_diffuse_incidence_source (ms_source_lookup.glsl), peak_beam_phase (phase_function.glsl) and the slab
// transmittances (slab_transmittance.glsl) for a buffer of inputs, so the test can compare
// them with model::MsSourceTable::lookup of both tables, model::peak_beam_phase and
// model::slab_beam_transmittance / slab_diffuse_transmittance in double precision.
//   in_a[i] = (tau_a, tau_b, mu_s, mu_w), in_b[i] = (phi_deg, cos_theta, tau, diffuse)
//   u_phase = (g_HG, g_D, alpha, w_D)
//   out_result[i] = (J_d / mu_s of the sun's table, or J of the diffuse table where
//   diffuse > 1.5; depth coordinate; peak beam; transmittance of a slab of optical depth
//   tau_a + tau_b: of diffuse light where diffuse > 0.5, else of the beam at mu_s)
#include "common.glsl"
#include "phase_function.glsl"
#include "ms_source_lookup.glsl"
#include "slab_transmittance.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = SSBO_TEST_INPUT_A) readonly buffer InA { vec4 in_a[]; };
layout(std430, binding = SSBO_TEST_INPUT_B) readonly buffer InB { vec4 in_b[]; };
layout(std430, binding = SSBO_TEST_OUTPUT) writeonly buffer Result { vec4 out_result[]; };
uniform uint u_count;
uniform vec4 u_phase;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  vec4 a = in_a[i];
  vec4 b = in_b[i];
  float source = b.w > 1.5 ? ms_diffuse_incidence_source(a.x, a.y, a.w) : ms_source_over_mu(a.x, a.y, a.z, a.w, b.x);
  out_result[i] = vec4(source, ms_depth_coordinate(a.x, a.y),
                       peak_beam_phase(b.y, b.z, u_phase.x, u_phase.y, u_phase.z, u_phase.w),
                       b.w > 0.5 ? slab_diffuse_transmittance(a.x + a.y) : slab_beam_transmittance(a.x + a.y, a.z));
}
