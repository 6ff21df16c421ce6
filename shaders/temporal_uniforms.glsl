// Per-frame constants of the cloud buffer and its temporal reuse, std140. Mirrors
// renderer/temporal_uniforms.h (keep in sync).
// The cloud buffer holds, per cloud pixel, the clouds along its ray: premultiplied
// in-scattered radiance and transmittance (a), and depth, ground optical depth, layer and
// history length (b). It is 1/divisor of the frame in each axis. Each frame marches the
// pixels (stride * i + offset) of it ("fresh" samples); the rest come from the previous
// frame's buffer, reprojected (renderer/temporal_reprojection.h).

layout(std140, binding = 1) uniform TemporalUniforms {
  mat4 reproject[5];  // current local frame -> previous local frame (m), for the cloud field of
                      // layer 0..3 (camera motion and that layer's wind) and for the ground (4)
  vec4 prev_forward;  // previous camera axes, in the previous local frame
  vec4 prev_right;
  vec4 prev_up;
  vec4 prev_view;     // x tan(hfov/2), y tan(vfov/2) of the previous frame
  ivec4 grid;         // x stride, y/z offset of this frame's fresh samples, w history valid (0/1)
  ivec4 buffer_size;  // x, y cloud buffer size (px), z divisor (frame px per cloud px), w neighbourhood clamp (0/1)
  vec4 blend;         // x minimum weight of a fresh sample, y camera still (1/0), z..w unused
} TU;

// Normalised device coordinates of the centre of cloud pixel q (frame pixels grouped
// divisor x divisor; y up).
vec2 cloud_pixel_ndc(vec2 q) {
  vec2 full = (q + 0.5) * float(TU.buffer_size.z);
  vec2 ndc = full / U.view.zw * 2.0 - 1.0;
  return vec2(ndc.x, -ndc.y);
}

vec3 view_ray(vec2 ndc) {
  return normalize(U.camera_forward.xyz + ndc.x * U.view.x * U.camera_right.xyz + ndc.y * U.view.y * U.camera_up.xyz);
}
