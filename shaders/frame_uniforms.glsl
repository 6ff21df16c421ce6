// Per-frame constants, std140. Mirrors renderer/frame_uniforms.h (keep in sync).
// Frame: "local" = East-North-Up axes at the camera, origin at the camera, metres.
// The cloud shell and ground are spheres of radius planet.x (the osculating sphere of
// the WGS84 ellipsoid at the camera, DESIGN.md §2) centred at (0, 0, -(R + h)).

struct CloudLayerGpu {
  vec4 altitude;       // x base (m), y top (m), z coverage [0,1], w density scale
  vec4 optics;         // x sigma_t max (1/m), y g_HG, z g_D, w Draine alpha
  vec4 optics2;        // x w_D, y 1/base noise period (1/m), z 1/detail period (1/m), w detail erosion
  vec4 profile;        // x bottom ramp, y top ramp, z top weight, w noise vertical scale k
  vec4 base_offset;    // xyz offset of the base noise in tile units (ECEF axes), wrapped; w stratiform (1/0)
  vec4 detail_offset;  // xyz offset of the detail noise in tile units, wrapped
  mat4 noise_rotation; // upper 3x3: local ENU -> ECEF axes of the wind-rotated field (renderer/wind_drift.h)
};

layout(std140, binding = 0) uniform FrameUniforms {
  mat4 enu_to_ecef;        // rotation (upper 3x3): local ENU axes -> ECEF axes
  vec4 camera_forward;     // xyz, local ENU
  vec4 camera_right;       // xyz, local ENU
  vec4 camera_up;          // xyz, local ENU
  vec4 view;               // x tan(hfov/2), y tan(vfov/2), z width px, w height px
  vec4 planet;             // x shell radius R (m), y camera altitude h (m), z ground altitude (m), w max cloud march distance (m)
  vec4 sun_dir;            // xyz unit vector to the sun, local ENU; w cos(solar angular radius)
  vec4 sun_irradiance;     // rgb solar spectral irradiance at the top of the atmosphere (W m^-2 nm^-1)
  vec4 ground_albedo;      // rgb diffuse albedo of the ground; w night-sky radiance (W m^-2 sr^-1 nm^-1)
  vec4 quality;            // x primary steps, y light steps, z multiple-scattering octaves, w ground-shadow steps per layer
  vec4 ms_params;          // x a (extinction scale per octave), y b (energy per octave), z c (eccentricity per octave), w t_ref of the step distribution (m; 0 = uniform)
  vec4 ap_params;          // x aerial-perspective max distance (m), y weather map height (texels), z weight of the next weather keyframe, w unused
  vec4 march;              // x long-step factor in empty air (1 = off), y LOD on (0/1), z pixel angle (rad), w mean detail-noise value
  vec4 skips;              // x coverage pyramid on (1/0), y light-march optical-depth cut-off (1e30 = none), zw unused
  vec4 ap_forward;         // frustum of the aerial-perspective volume (local ENU): xyz forward,
  vec4 ap_right;           //   xyz right, w tan(half its width),
  vec4 ap_up;              //   xyz up, w tan(half its height)
  ivec4 counts;            // x layer count, y frame index, z count density evaluations (0/1), w footprint jitter (0/1)
  vec4 noise_quantiles[4]; // base shape noise value below which a fraction i/15 of texels lie, i = 0..15
  vec4 weather_pole_south; // weather map value at the south pole (mean of the southernmost row)
  vec4 weather_pole_north; // ... at the north pole
  CloudLayerGpu layers[4];
} U;
