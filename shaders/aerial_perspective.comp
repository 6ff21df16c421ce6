#version 450 core
// Aerial-perspective volume (Hillaire 2020 §5.4, extended to flight distances): for each
// of 32x32 view directions through its frustum (frame.ap_forward/right/up: the camera's, a
// little wider, kept while the camera turns within it), in-scattered radiance (unit sun)
// and transmittance from the camera to 32 distances d_k = d_max (k / 31)^2, k = 0..31, with
// d_max = frame.ap_max_distance_m (hundreds of km). One invocation marches one column.
#include "common.glsl"
#include "frame_uniforms.glsl"
#include "atmosphere_model.glsl"
#include "atmosphere_lookup.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = IMG_AP_INSCATTER_OUT) uniform writeonly image3D out_inscatter;
layout(rgba32f, binding = IMG_AP_TRANSMITTANCE_OUT) uniform writeonly image3D out_transmittance;

const int SUBSTEPS = 3;

void main() {
  ivec3 size = imageSize(out_inscatter);
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, size.xy))) return;
  vec2 ndc = (vec2(px) / vec2(size.xy - 1)) * 2.0 - 1.0;
  vec3 d = normalize(frame.ap_forward + ndc.x * frame.ap_tan_half_width * frame.ap_right + ndc.y * frame.ap_tan_half_height * frame.ap_up);
  float r = atmo_radius(frame.camera_altitude_m);
  vec3 sun = frame.sun_direction;
  float nu = dot(d, sun);
  float d_max = frame.ap_max_distance_m;
  vec3 L = vec3(0.0), T = vec3(1.0);
  float t_prev = 0.0;
  imageStore(out_inscatter, ivec3(px, 0), vec4(0.0, 0.0, 0.0, 1.0));
  imageStore(out_transmittance, ivec3(px, 0), vec4(1.0));
  for (int k = 1; k < size.z; ++k) {
    float f = float(k) / float(size.z - 1);
    float t_next = d_max * f * f;
    float dt = (t_next - t_prev) / float(SUBSTEPS);
    for (int s = 0; s < SUBSTEPS; ++s) {
      float t = t_prev + (float(s) + 0.5) * dt;
      vec3 x = vec3(0.0, 0.0, r) + t * d;
      float rx = length(x);
      float alt = rx - ATMO_BOTTOM;
      if (alt < ATMO_TOP - ATMO_BOTTOM) {
        AtmoMedium m = atmo_medium(alt);
        vec3 S = atmo_inscatter_density(m, alt, dot(x, sun) / rx, nu);
        vec3 step_T = exp(-m.extinction * dt);
        L += T * S * (vec3(1.0) - step_T) / max(m.extinction, vec3(1e-12));
        T *= step_T;
      }
    }
    t_prev = t_next;
    imageStore(out_inscatter, ivec3(px, k), vec4(L, 1.0));
    imageStore(out_transmittance, ivec3(px, k), vec4(T, 1.0));
  }
}
