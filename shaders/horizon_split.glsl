// A pixel's footprint split at the horizon. The cloud march (cloud_march.comp) marches both
// parts of a footprint the horizon crosses, and the composite (composite.comp) weights the
// ground and the sky behind them by the same box-filter fraction. Needs frame_uniforms.glsl
// and temporal_uniforms.glsl (view_ray) before it.

// Fraction of a pixel below the horizon. The elevation e over the pixel is taken as linear
// in the pixel's two axes: e = e_c + u + v with u, v uniform over widths a, b (e's change
// across the pixel along its width and its height), so the fraction with e < e_h is the
// CDF of the sum of two uniforms at e_h - e_c: a trapezoid, piecewise quadratic (exact for
// a straight horizon over a square box filter).
float below_fraction(float z, float a, float b) {  // P(u + v < z), widths a, b
  float w1 = max(a, b), w2 = min(a, b);
  float hs = 0.5 * (w1 + w2), hd = 0.5 * (w1 - w2);
  if (z <= -hs) return 0.0;
  if (z >= hs) return 1.0;
  float zs = abs(z);
  float upper = zs < hd ? (zs + 0.5 * w1) / w1 : 1.0 - (hs - zs) * (hs - zs) / (2.0 * w1 * max(w2, 1e-12));
  return z >= 0.0 ? upper : 1.0 - upper;
}

// dir turned in its vertical plane to elevation e (radians); dir not vertical.
vec3 at_elevation(vec3 dir, float e) {
  vec2 hz = normalize(dir.xy);
  return vec3(hz * cos(e), sin(e));
}

// Elevation (rad) of the view ray through ndc above the camera's local horizontal.
float ray_elevation(vec2 ndc) { return asin(clamp(view_ray(ndc).z, -1.0, 1.0)); }

// Elevation (rad) of the horizon seen from the camera: -dip, cos(dip) = (R + ground) / (R + h),
// written as 2 asin(sqrt((h - ground) / (2 (R + h)))) (no cancellation at h of metres).
float horizon_elevation() {
  float h = frame.camera_altitude_m;
  return -2.0 * asin(sqrt(max(h - frame.ground_altitude_m, 0.0) / (2.0 * (frame.shell_radius_m + h))));
}

// The split of a footprint centred on the ray through ndc (direction dir), half_ndc its
// half size in ndc (x right, y up): the fraction f_ground below the horizon (box filter),
// and the elevation range the footprint spans below (e_lo .. e_h) and above (e_h .. e_hi)
// it. f_ground is 0 or 1 where the horizon does not cross the footprint (then e_lo, e_hi
// are not set). The elevation change across the footprint comes from the ray elevations at
// its edges; it reaches the horizon only within sqrt(2) of its half width's angle.
struct HorizonFootprint {
  float f_ground;
  float e_lo, e_h, e_hi;
};

HorizonFootprint footprint_at_horizon(vec2 ndc, vec2 half_ndc, vec3 dir) {
  float e_c = asin(clamp(dir.z, -1.0, 1.0));
  float e_h = horizon_elevation();
  HorizonFootprint fp = HorizonFootprint(e_c < e_h ? 1.0 : 0.0, e_c, e_h, e_c);
  if (abs(e_c - e_h) >= 1.5 * frame.tan_half_fov_x * abs(half_ndc.x) || abs(dir.z) >= 0.999) return fp;
  // elevation change across the footprint along its width and its height
  float ex = ray_elevation(ndc + vec2(half_ndc.x, 0.0)) - ray_elevation(ndc - vec2(half_ndc.x, 0.0));
  float ey = ray_elevation(ndc + vec2(0.0, half_ndc.y)) - ray_elevation(ndc - vec2(0.0, half_ndc.y));
  float f = below_fraction(e_h - e_c, abs(ex), abs(ey));
  if (f <= 0.0 || f >= 1.0) return fp;
  float half_range = 0.5 * (abs(ex) + abs(ey));
  fp.f_ground = f;
  fp.e_lo = min(e_c - half_range, e_h);
  fp.e_hi = max(e_c + half_range, e_h);
  return fp;
}

bool crosses_horizon(HorizonFootprint fp) { return fp.f_ground > 0.0 && fp.f_ground < 1.0; }
