// Per-frame constants of the cloud buffer and its temporal reuse, std140: the GLSL side of
// renderer/temporal_uniforms.h (member comments there).
// The cloud buffer holds, per cloud pixel, the clouds along its ray: premultiplied
// in-scattered radiance and transmittance (radiance texture), and depth, ground-share shift
// (cloud_march.comp), layer and history length (depth texture). It is 1/divisor of the frame in each axis. Each frame
// marches the pixels (stride * i + offset) of it ("fresh" samples); the rest come from the
// previous frame's buffer, reprojected (renderer/temporal_reprojection.h).

layout(std140, binding = UBO_TEMPORAL) uniform TemporalUniforms {
  mat4 reproject[MAX_LAYERS + 1];
  vec3 prev_forward;
  float prev_tan_half_fov_x;
  vec3 prev_right;
  float prev_tan_half_fov_y;
  vec3 prev_up;
  float history_blend_min;
  ivec2 cloud_buffer_size;
  int fresh_stride;
  int history_valid;
  ivec2 fresh_offset;
  int cloud_divisor;
  int neighbourhood_clamp;
  int camera_still;
  int footprint_sample;
  float prev_center_tan_x;
  float prev_center_tan_y;
} temporal;

// Normalised device coordinates of the centre of cloud pixel q (frame pixels grouped
// divisor x divisor; y up).
vec2 cloud_pixel_ndc(vec2 q) {
  vec2 full = (q + 0.5) * float(temporal.cloud_divisor);
  vec2 ndc = full / frame.image_size_px * 2.0 - 1.0;
  return vec2(ndc.x, -ndc.y);
}

vec3 view_ray(vec2 ndc) {
  return normalize(frame.camera_forward + (frame.view_center_tan_x + ndc.x * frame.tan_half_fov_x) * frame.camera_right +
                   (frame.view_center_tan_y + ndc.y * frame.tan_half_fov_y) * frame.camera_up);
}
