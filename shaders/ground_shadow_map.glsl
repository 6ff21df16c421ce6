// The ground shadow map (ground_shadow_map.comp, renderer/ground_shadow_map.h): per cloud
// layer, the optical depth of that layer towards the sun above each ground point around
// the camera where the map was built (the anchor), stored in the anchor's local frame with
// a radial warp u = d / (|d| + K) of the horizontal offset d (m): texels of 2K/N metres
// under the anchor growing with (|d| + K)^2 / K outwards, the whole ground out to the
// horizon in one map. The layers' fields drift with their wind after the build; a lookup
// first carries the ground point back along its layer's drift.

// std140: the GLSL side of renderer/shadow_map_uniforms.h (member comments there).
layout(std140, binding = UBO_SHADOW_MAP) uniform ShadowMapUniforms {
  mat4 to_anchor[MAX_LAYERS];
  float warp_m;
  int map_texels;
  int map_valid;
  int march_per_pixel;
  int volume_levels;
  int volume_texels;
  int volume_valid;
  int column_valid;
  int column_march_steps;
} shadow;

layout(binding = TEX_GROUND_SHADOW_MAP) uniform sampler2DArray ground_shadow;  // the map (read where map_valid)

// Map coordinates [0,1]^2 of a point given in the anchor's local frame.
vec2 shadow_map_uv(vec3 q) {
  vec2 d = q.xy;
  float len = length(d);
  vec2 u = d / (len + shadow.warp_m);
  return u * 0.5 + 0.5;
}

// Inverse: the horizontal offset d (m) of map coordinates uv.
vec2 shadow_map_offset(vec2 uv) {
  vec2 u = uv * 2.0 - 1.0;
  float r = length(u);
  return u * shadow.warp_m / max(1.0 - r, 1e-6);
}

// The point at horizontal offset d (m, the anchor's local frame) and altitude alt: on the
// sphere of radius R + alt around (0, 0, -(R + h)), z = sqrt((R+alt)^2 - |d|^2) - (R+h)
// written without cancellation. False where |d| reaches past that sphere.
bool point_at_offset(vec2 d, float alt, out vec3 p) {
  float R = frame.shell_radius_m, h = frame.camera_altitude_m;
  float d2 = dot(d, d);
  p = vec3(d, 0.0);
  if (d2 >= (R + alt) * (R + alt)) return false;
  p.z = ((alt - h) * (2.0 * R + alt + h) - d2) / (sqrt((R + alt) * (R + alt) - d2) + R + h);
  return true;
}

// Layer li's optical depth towards the sun above ground point p (local frame): the map's
// texel, after carrying p back along the layer's drift (shadow.to_anchor).
float shadow_map_optical_depth(int li, vec3 p) {
  return textureLod(ground_shadow, vec3(shadow_map_uv((shadow.to_anchor[li] * vec4(p, 1.0)).xyz), float(li)), 0.0).r;
}
