#version 450 core
// Sky-view LUT (Hillaire 2020 §5.3): in-scattered radiance around the camera for unit
// solar irradiance, parameterised by view zenith (non-linear, dense at the horizon) and
// azimuth relative to the sun (u^2 mapping, symmetric about the sun's vertical plane).
#include "common.glsl"
#include "frame_uniforms.glsl"
#include "atmosphere_model.glsl"
#include "atmosphere_lookup.glsl"
#include "sky_view_mapping.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = IMG_LUT_OUT) uniform writeonly image2D out_lut;

const int STEPS = 30;

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(out_lut);
  if (any(greaterThanEqual(px, size))) return;
  float r = atmo_radius(frame.camera_altitude_m);
  float mu_sun = frame.sun_direction.z;
  vec3 sun = vec3(sqrt(max(0.0, 1.0 - mu_sun * mu_sun)), 0.0, mu_sun);
  vec3 d = sky_view_direction(vec2(px) / vec2(size - 1), r);
  float len = atmosphere_path_length(r, d.z);
  vec3 L, T;
  march_atmosphere(r, d, sun, len, STEPS, L, T);
  imageStore(out_lut, px, vec4(L, 1.0));
}
