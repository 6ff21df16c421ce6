// Sky-view LUT mapping (Hillaire 2020 §5.3): v in [0, 0.5] covers zenith..horizon with a
// quadratic squeeze towards the horizon, v in [0.5, 1] horizon..nadir; u = sqrt(azimuth
// from the sun / pi). Frame: z up, sun in the x-z plane (azimuth 0).

// uv: unit parameters in [0, 1] (texel px of an n-texel axis has uv = px / (n - 1)).
vec3 sky_view_direction(vec2 uv, float r) {
  // beta: angle between the nadir and the horizon direction (Hillaire's "Beta");
  // the horizon lies at zenith angle pi - beta.
  float horizon_cos = -sqrt(max(0.0, 1.0 - (ATMO_BOTTOM / r) * (ATMO_BOTTOM / r)));
  float beta = acos(clamp(-horizon_cos, -1.0, 1.0));
  float zenith_horizon = PI - beta;
  float theta;
  if (uv.y < 0.5) {
    float c = 1.0 - 2.0 * uv.y;
    theta = zenith_horizon * (1.0 - c * c);
  } else {
    float c = 2.0 * uv.y - 1.0;
    theta = zenith_horizon + beta * c * c;
  }
  float phi = uv.x * uv.x * PI;
  return vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
}

vec2 sky_view_uv(vec3 d_rel_sun, float r, vec2 size) {
  float horizon_cos = -sqrt(max(0.0, 1.0 - (ATMO_BOTTOM / r) * (ATMO_BOTTOM / r)));
  float beta = acos(clamp(-horizon_cos, -1.0, 1.0));
  float zenith_horizon = PI - beta;
  float theta = acos(clamp(d_rel_sun.z, -1.0, 1.0));
  float v;
  if (theta < zenith_horizon) {
    float c = 1.0 - theta / zenith_horizon;
    v = 0.5 * (1.0 - sqrt(max(c, 0.0)));
  } else {
    float c = (theta - zenith_horizon) / max(beta, 1e-6);
    v = 0.5 + 0.5 * sqrt(saturate(c));
  }
  float phi = atan(abs(d_rel_sun.y), d_rel_sun.x);  // [0, pi]
  float u = sqrt(phi / PI);
  // texel-centre mapping
  return vec2(0.5 / size.x + u * (1.0 - 1.0 / size.x), 0.5 / size.y + v * (1.0 - 1.0 / size.y));
}
