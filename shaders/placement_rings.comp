#version 450 core
// Fills one ring of a cumulus layer's dome rings (weather::dome_ring_texel,
// weather/cumulus_domes.h): per texel, at the shell point of its centre, the unit-aspect dome
// top of the ring's own placement levels under the warp octaves its texel draws (each cloud
// accepted by the weather map's coverage at its own centre), never below -floor, and the
// fraction the finer levels cover (CloudPlacement::covered_below). Field frame: ECEF axes
// turned with the layer's wind (weather/wind_drift.h), metres, relative to the ring's centre
// C on the shell.
#include "common.glsl"
#include "weather_map_sampling.glsl"
#include "cloud_placement.glsl"
#include "gradient_noise.glsl"
#include "dome_warp.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

struct RingJob {
  PlacementFrame pf;     // centre = C; the levels' cubes around it
  DomeWarpFrame warp;    // the warp's octaves around C
  mat4 field_to_ecef;    // upper 3 x 3: field axes -> ECEF axes
  vec4 plane_e, plane_n; // xyz: unit tangents at C (RingPlane e, n)
  vec4 pole_south, pole_north;  // the weather map's pole values (blended keyframes)
  vec2 origin;           // the ring's centre on the plane (m; weather::DomeRings::origin)
  float texel_m;         // h_k
  int size;              // texels a side
  int first_level;       // the ring's levels: [first_level, end_level)
  int end_level;
  int warp_octaves;      // the warp octaves drawn (dome_warp_octaves)
  float floor_m;         // the top's floor (dome_ring_floor_m)
  int slice;             // layer of the ring texture array
  float layer_coverage;  // the layer's own coverage c_L
  float map_height;      // weather map rows
  float map_blend;       // weight of the next keyframe
  int table_steps;       // the acceptance table's coverage steps (rows - 1)
};

layout(std430, binding = SSBO_PLACEMENT_RING_JOB) readonly buffer Job {
  RingJob job;
  float acceptance_table[];  // row i (coverage i / table_steps): p_k of each level k
};
layout(rg32f, binding = IMG_PLACEMENT_RINGS_OUT) writeonly uniform image2DArray rings_out;

// The layer's local coverage at the shell point C + x (x relative to C, field frame).
float coverage_at(vec3 x) {
  vec3 q = mat3(job.field_to_ecef) * (job.pf.centre + x);
  vec4 w = weather_map_at(q, job.map_height, job.map_blend, job.pole_south, job.pole_north);
  return modulated_coverage(job.layer_coverage, w.r);
}

// p_k at coverage c, interpolated in the table as CloudPlacement::level_acceptance does.
float acceptance_at(int level, float c) {
  float x = clamp(c, 0.0, 1.0) * float(job.table_steps);
  int i = min(int(x), job.table_steps - 1);
  float f = x - float(i);
  int n = job.pf.levels;
  return mix(acceptance_table[i * n + level], acceptance_table[(i + 1) * n + level], f);
}

float placement_acceptance(PlacementFrame pf, int level, vec3 centre) { return acceptance_at(level, coverage_at(centre)); }

// The shell point at plane coordinates uv, relative to C (ring_point_from_centre).
vec3 ring_point(vec2 uv) {
  float R = job.pf.shell_radius_m;
  vec3 c = normalize(job.pf.centre);
  vec3 w = (uv.x * job.plane_e.xyz + uv.y * job.plane_n.xyz) / R;
  float w2 = dot(w, w), s = sqrt(1.0 + w2);
  return R * (w / s - c * (w2 / (s * (1.0 + s))));
}

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, ivec2(job.size)))) return;
  vec2 uv = job.origin + (vec2(t) + 0.5 - 0.5 * float(job.size)) * job.texel_m;
  vec3 x = ring_point(uv);
  float top = -job.floor_m;
  if (job.first_level < job.end_level)
    top = placement_dome_top(job.pf, dome_warped(job.warp, job.pf, x, job.warp_octaves), job.first_level, job.end_level,
                             job.floor_m);
  // covered_below: 1 - exp(-sum_{k < first} p_k pi <rho^2>), <rho^2> over rho uniform in [a, b]
  float a = job.pf.rho_min, b = job.pf.rho_max;
  float mean_rho2 = b > a ? (b * b * b - a * a * a) / (3.0 * (b - a)) : a * a;
  float c = coverage_at(x), depth = 0.0;
  for (int k = 0; k < min(job.first_level, job.pf.levels); ++k) depth += acceptance_at(k, c) * PI * mean_rho2;
  imageStore(rings_out, ivec3(t, job.slice), vec4(top, 1.0 - exp(-depth), 0.0, 0.0));
}
