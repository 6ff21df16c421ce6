// The column volume (column_volume.comp, renderer/ground_shadow_map.h): per cloud layer, the
// optical depths of that layer's cloud straight above and straight below a point inside it
// (its own vertical column: the independent column approximation, Cahalan et al. 1994), on
// the ground shadow map's warped horizontal grid around the anchor (ground_shadow_map.glsl),
// COLUMN_VOLUME_TEXELS per side, at COLUMN_VOLUME_LEVELS + 1 altitude nodes from the
// layer's base (node 0) to its top (node COLUMN_VOLUME_LEVELS), cosine-spaced
// (column_node_fraction): R the depth below
// the node, G the depth above. The depths at which diffuse_inscatter (cloud_lighting.glsl)
// reads its source tables when RenderQuality::column_steps > 0. The lookup follows the
// layers' wind drift like the ground shadow map. Needs frame_uniforms.glsl and
// ground_shadow_map.glsl.

layout(binding = TEX_COLUMN_VOLUME) uniform sampler3D column_volume;  // N x N x (nodes * MAX_LAYERS), rg16f

const int COLUMN_VOLUME_NODES = COLUMN_VOLUME_LEVELS + 1;

// Height of node coordinate x in [0, 1] (node k at x = k / COLUMN_VOLUME_LEVELS) as a
// fraction of the layer's thickness: cosine spacing, 0.11 % of the thickness between the
// first two nodes and 3.3 % in the middle (48 levels). A view grazing a deck's base sees
// the radiance of its lowest metres, where the depth below a point grows from 0 within
// metres: 33 equally spaced nodes interpolated it linearly over 1/32 of the layer there
// (the base 5 % bright near the horizon, tests/render_column_depths_test.cpp).
float column_node_fraction(float x) { return 0.5 - 0.5 * cos(PI * x); }

// Its inverse: the node coordinate of height fraction f.
float column_node_coordinate(float f) { return acos(clamp(1.0 - 2.0 * f, -1.0, 1.0)) / PI; }

// Optical depths (below, above) of layer li's column through local point p at altitude
// alt: trilinear between the grid's columns and the two nodes around alt.
vec2 column_volume_depths(int li, vec3 p, float alt) {
  vec3 q = (shadow.to_anchor[li] * vec4(p, 1.0)).xyz;
  vec2 uv = shadow_map_uv(q);
  float base = frame.layers[li].base_m, top = frame.layers[li].top_m;
  // node coordinate in [0, levels], kept inside this layer's slices of the texture
  float k = column_node_coordinate((alt - base) / (top - base)) * float(COLUMN_VOLUME_LEVELS);
  float z = (float(li * COLUMN_VOLUME_NODES) + k + 0.5) / float(MAX_LAYERS * COLUMN_VOLUME_NODES);
  return textureLod(column_volume, vec3(uv, z), 0.0).rg;
}
