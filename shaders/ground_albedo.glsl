// The ground's albedo where weather-map tiles set it (weather/ground_albedo_map.h;
// renderer/ground_albedo_texture.h). Needs frame_uniforms.glsl and weather_map_sampling.glsl.

layout(binding = TEX_GROUND_ALBEDO) uniform sampler2D ground_albedo_map;  // REPEAT in lon

// The ground's albedo (rgb) in the direction q: the weather's global albedo where no tile
// has set one, else the tiles' grey albedo blended with it (weather/ground_albedo_map.h:
// R = albedo x weight, G = weight, so albedo = R + (1 - G) global). The map has the weather
// map's grid.
vec3 ground_albedo_at(vec3 q) {
  vec3 global = frame.ground_albedo.rgb;
  if (frame.ground_albedo.w == 0.0) return global;
  vec2 uv = map_uv(q);
  vec2 rg = textureLod(ground_albedo_map, uv, 0.0).rg;
  vec2 pw = map_pole_weights(uv.y, frame.weather_map_height);
  rg = mix(mix(rg, frame.ground_albedo_poles.xy, pw.x), frame.ground_albedo_poles.zw, pw.y);
  return vec3(rg.x) + (1.0 - rg.y) * global;
}
