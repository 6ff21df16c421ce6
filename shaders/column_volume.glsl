// The column volume (column_volume.comp, renderer/ground_shadow_map.h): per cloud layer, the
// optical depths of that layer's cloud straight above and straight below a point inside it
// (its own vertical column: the independent column approximation, Cahalan et al. 1994), on
// the ground shadow map's warped horizontal grid around the anchor (ground_shadow_map.glsl),
// COLUMN_VOLUME_TEXELS per side, at COLUMN_VOLUME_LEVELS + 1 equally spaced altitude nodes
// from the layer's base (node 0) to its top (node COLUMN_VOLUME_LEVELS): R the depth below
// the node, G the depth above. The depths at which diffuse_inscatter (cloud_lighting.glsl)
// reads its source tables when RenderQuality::column_steps > 0. The lookup follows the
// layers' wind drift like the ground shadow map. Needs frame_uniforms.glsl and
// ground_shadow_map.glsl.

layout(binding = TEX_COLUMN_VOLUME) uniform sampler3D column_volume;  // N x N x (nodes * MAX_LAYERS), rg16f

const int COLUMN_VOLUME_NODES = COLUMN_VOLUME_LEVELS + 1;

// Optical depths (below, above) of layer li's column through local point p at altitude
// alt: trilinear between the grid's columns and the two nodes around alt.
vec2 column_volume_depths(int li, vec3 p, float alt) {
  vec3 q = (shadow.to_anchor[li] * vec4(p, 1.0)).xyz;
  vec2 uv = shadow_map_uv(q);
  float base = frame.layers[li].base_m, top = frame.layers[li].top_m;
  // node coordinate in [0, levels], kept inside this layer's slices of the texture
  float k = clamp((alt - base) / (top - base), 0.0, 1.0) * float(COLUMN_VOLUME_LEVELS);
  float z = (float(li * COLUMN_VOLUME_NODES) + k + 0.5) / float(MAX_LAYERS * COLUMN_VOLUME_NODES);
  return textureLod(column_volume, vec3(uv, z), 0.0).rg;
}
