// The light volume (light_volume.comp, renderer/ground_shadow_map.h): per cloud layer, the
// optical depth of that layer from a point inside it towards the sun, on the ground shadow
// map's warped horizontal grid around the anchor (ground_shadow_map.glsl) times
// float(shadow.volume_levels) altitude levels through the layer. Replaces the per-sample light march when
// RenderQuality::light_volume is on: one trilinear lookup instead of light_steps density
// evaluations, at the cost of the grid's resolution (the lookup follows the wind drift like
// the ground shadow map). Needs frame_uniforms.glsl and ground_shadow_map.glsl.

layout(binding = TEX_LIGHT_VOLUME) uniform sampler3D light_volume;  // N x N x (levels * MAX_LAYERS), r32f

// Altitude (m) of level k (0 .. levels - 1) of layer li: the centres of equal slices.
float light_volume_altitude(int li, float k) {
  vec2 a = vec2(frame.layers[li].base_m, frame.layers[li].top_m);
  return a.x + (k + 0.5) / float(shadow.volume_levels) * (a.y - a.x);
}

// Optical depth towards the sun of layer li from local point p at altitude alt.
float light_volume_optical_depth(int li, vec3 p, float alt) {
  vec3 q = (shadow.to_anchor[li] * vec4(p, 1.0)).xyz;
  vec2 uv = shadow_map_uv(q);
  vec2 a = vec2(frame.layers[li].base_m, frame.layers[li].top_m);
  float levels = float(shadow.volume_levels);
  // level coordinate, clamped to the outer level centres of this layer's slab
  float k = clamp((alt - a.x) / (a.y - a.x) * levels, 0.5, levels - 0.5);
  float z = (float(li) * levels + k) / (float(MAX_LAYERS) * levels);
  return textureLod(light_volume, vec3(uv, z), 0.0).r;
}
