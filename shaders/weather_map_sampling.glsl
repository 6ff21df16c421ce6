// The global weather map (weather/weather_map.h) as the shaders read it: bilinear in an
// equirectangular latitude/longitude grid, repeating in longitude, blended to the pole's
// value within half a row of a pole, and the next keyframe mixed in while it fades in.
// Needs common.glsl.

layout(binding = TEX_WEATHER_MAP) uniform sampler2D weather_map;           // REPEAT in lon
layout(binding = TEX_WEATHER_MAP_NEXT) uniform sampler2D weather_map_next;  // the next keyframe
// the keyframes' layer-coverage channels (forecast weather; weather::WeatherMap::layer_coverage):
// the maps' size, or 1 x 1 of zeros for a keyframe without them
layout(binding = TEX_LAYER_COVERAGE) uniform sampler2D layer_coverage_map;
layout(binding = TEX_LAYER_COVERAGE_NEXT) uniform sampler2D layer_coverage_map_next;

// Latitude and longitude (rad) of the direction q from the shell centre, as the weather map
// is indexed. atan2 for latitude keeps full precision near the poles (asin would lose ~km
// there in float).
vec2 map_lat_lon(vec3 q) { return vec2(atan(q.z, length(q.xy)), atan(q.y, q.x)); }

// Texture coordinates of the direction q (ECEF axes, any length) in an equirectangular map.
vec2 map_uv(vec3 q) {
  vec2 ll = map_lat_lon(q);
  return vec2(ll.y * (0.5 / PI) + 0.5, ll.x / PI + 0.5);
}

// Within half a texel row of a pole a map's value blends to the pole's (as WeatherMap::sample
// does): every longitude meets at the same value, no pinwheel at the pole. The weights of
// the south pole's value (x) and the north's (y) at texture row v of a map of map_height
// rows; both 0 away from the poles.
vec2 map_pole_weights(float v, float map_height) {
  float y = v * map_height - 0.5;
  return vec2(y < 0.0 ? min(1.0, -2.0 * y) : 0.0, y > map_height - 1.0 ? min(1.0, 2.0 * (y - map_height + 1.0)) : 0.0);
}

// A pair of keyframe textures (this one, the next at weight blend) in the direction q, for
// maps of map_height rows, blended within half a row of a pole to the poles' values (the
// rows' means).
vec4 keyframes_at(sampler2D now_map, sampler2D next_map, vec3 q, float map_height, float blend, vec4 pole_south,
                  vec4 pole_north) {
  vec2 uv = map_uv(q);
  // the next keyframe only while one is fading in (a uniform branch: no divergence)
  vec4 w = textureLod(now_map, uv, 0.0);
  if (blend > 0.0) w = mix(w, textureLod(next_map, uv, 0.0), blend);
  vec2 pw = map_pole_weights(uv.y, map_height);
  return mix(mix(w, pole_south, pw.x), pole_north, pw.y);
}

// The weather map in the direction q.
vec4 weather_map_at(vec3 q, float map_height, float blend, vec4 pole_south, vec4 pole_north) {
  return keyframes_at(weather_map, weather_map_next, q, map_height, blend, pole_south, pole_north);
}

// The layer-coverage channels in the direction q (the same texels, blends and poles).
vec4 layer_coverage_map_at(vec3 q, float map_height, float blend, vec4 pole_south, vec4 pole_north) {
  return keyframes_at(layer_coverage_map, layer_coverage_map_next, q, map_height, blend, pole_south, pole_north);
}

// A layer's coverage c modulated by the map's coverage channel m (weather::local_coverage).
float modulated_coverage(float c, float m) { return clamp(c + 1.2 * min(c, 1.0 - c) * (m - 0.5) * 2.0, 0.0, 1.0); }
