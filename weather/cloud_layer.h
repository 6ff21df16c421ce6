// Cloud layers: the weather state the renderer draws.
// Altitudes are metres above the WGS84 ellipsoid (the geoid undulation, |N| < 110 m,
// is ignored: MSL values are taken as ellipsoidal heights).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cloudsvc::weather {

// Cloud types, numbered as in CIGI 3.3 Weather Control (cloud type field).
enum class CloudType : int {
  None = 0,
  Altocumulus = 1,
  Altostratus = 2,
  Cirrocumulus = 3,
  Cirrostratus = 4,
  Cirrus = 5,
  Cumulonimbus = 6,
  Cumulus = 7,
  Nimbostratus = 8,
  Stratocumulus = 9,
  Stratus = 10,
};

// Lower-case name ("cumulus", "stratocumulus", ...) and its inverse (nullopt if unknown).
std::string_view cloud_type_name(CloudType t);
std::optional<CloudType> cloud_type_from_name(std::string_view name);

// Vertical density profile of a cloud type over the height fraction f in [0, 1] of its
// layer (0 = base, 1 = top). The shader evaluates
//   profile(f) = smoothstep(0, bottom_ramp, f) * (1 - smoothstep(1 - top_ramp, 1, f))
//                * mix(1, f, top_weight)   ... see shaders/cloud_density.glsl
// and the same numbers drive the CPU reference.
struct HeightProfile {
  float bottom_ramp = 0.1f;  // fraction of the layer over which density rises at the base
  float top_ramp = 0.3f;     // fraction over which density falls at the top
  float top_weight = 0.0f;   // 0: flat profile; 1: density grows linearly with height (anvils)
  float base_erosion = 0.5f; // 0..1: how strongly detail noise erodes (wispy edges)
};

// The profile above at height fraction x (ramps floored at 1e-3, as in the shader); 0
// outside (0, 1).
float height_profile(const HeightProfile& p, float x);

// The weather map's cloud-type channel t (G, weather/weather_map.h) selects the height
// profile per location, as the type channel of Schneider's Nubis weather map does: the
// cloud occupies the lowest fraction f_v(t) of its layer, with the layer type's profile
// scaled into it. In this model t spans the convective family, for convective layers
// (cumulus, cumulonimbus; CloudTypeTraits::stratiform false):
//   f_v(t) = clamp(0.5 + t, 0.3, 1)   (t >= 0: f_v in [0.5, 1]; the 0.3 floor is never reached)
//   t = 0     cells top out at half the layer depth (cumulus humilis in a cumulus layer;
//             towering cumulus reaching mid-layer in a cumulonimbus layer)
//   t = 0.25  three quarters of the depth (cumulus mediocris / congestus)
//   t >= 0.5  the full layer depth (the neutral value: the layer as specified; cumulus
//             congestus, or cumulonimbus to the layer top). Values above 0.5 change nothing.
// Stratiform layers ignore t (f_v = 1): their type (and so their profile) is the layer's.
// Stratus-like sheets are not reached through t: a map texel cannot turn a cumulus layer
// into stratus or a stratus layer into cumulus (that would need per-texel profile
// parameters in shaders/cloud_density.glsl).
float type_depth_fraction(float t, bool stratiform);

// Profile of a layer with profile p at height fraction f where the type channel is t:
// height_profile(p, f / f_v(t)) for f <= f_v(t), else 0. This is what
// shaders/cloud_density.glsl evaluates (and renderer/reference/cloud_field.cpp
// independently re-implements).
float type_height_profile(const HeightProfile& p, bool stratiform, float f, float t);

// The anvil of a convective layer: where the updrafts of cells that reach the top of the
// layer (the equilibrium level under the tropopause) meet the stable air above, the cloud
// spreads sideways into a thin ice shield many times the tower's width (Houze 1993, Cloud
// Dynamics, ch. 8; anvils 1-3 km deep), and the strongest cores overshoot above it. Over the
// band [base, top] of the layer's height fraction f (the layer's own fraction, not the
// type channel's scaled one: only cells that reach the band spread) the weight
//   w(f) = smoothstep(base, base + r, f) * (1 - smoothstep(top - r, top, f)),  r = (top - base) / 5
// rises sharply (the anvil's smooth flat base) and falls under the layer top (cores
// overshoot above the shield). Where w > 0 the cloud also fills where the shape exceeds the
// threshold of the wider coverage c_w = 1 - (1 - c)^(1 + spread w), at density_ratio times
// the tower's extinction (ice: IWC ~0.1-0.5 g/m^3 against the core's ~1.5 g/m^3 of liquid,
// Heymsfield et al. 2002): sigma ~ max(d(c), density_ratio d(c_w)). spread = 0: no anvil.
// shaders/cloud_density.glsl (anvil_weight, anvil_coverage) and
// renderer/reference/cloud_field.cpp evaluate it.
struct Anvil {
  float spread = 0.0f;         // 0: none; the exponent's growth at full weight
  float base = 0.78f;          // height fraction of the layer where the shield begins
  float top = 0.96f;           // ... and where it has thinned back to the towers
  float density_ratio = 0.15f; // shield extinction over the tower's, at the same d
};

// Typical values of a cloud type (defaults for layers that do not give their own; see
// weather/cloud_layer.cpp for the sources of each number).
//   default_density_scale multiplies the microphysical extinction
//     sigma_t = N0 * Q_ext * pi * (d / 2)^2,  N0 = 300 cm^-3, Q_ext = 2
//   (renderer/model/droplet_optics.h). It is chosen as LWC / LWC_N0(d): the type's typical
//   liquid (or ice) water content over the water content that N0 droplets of diameter d
//   would hold, so that sigma_t matches the type's typical water content.
//   stratiform: not convective (everything but cumulus and cumulonimbus): a sheet whose
//   depth is not driven by the weather map's cloud-type channel (type_depth_fraction).
struct CloudTypeTraits {
  HeightProfile profile;
  double default_base_m = 1000.0;
  double default_top_m = 2000.0;
  double default_droplet_diameter_um = 20.0;
  double default_density_scale = 1.0;
  double noise_scale_m = 8000.0;  // horizontal period of the base shape noise, m
  // Vertical frequency of the shape noise relative to the horizontal one: 1 = isotropic,
  // < 1 stretches features upwards (convective towers), > 1 flattens them (sheets).
  double noise_vertical_scale = 1.0;
  // How much finer the shape noise is along the Earth's axis (weather/noise_shaping.h):
  // 1 = isotropic; > 1 draws strands that run east-west (cirrus fibratus).
  double strand_ratio = 1.0;
  // Relief of the layer's base, as a fraction of its depth: 0 = the flat base of the height
  // profile; > 0 raises the base by up to this fraction with the detail noise (kBaseLiftMean
  // below), so a sheet's underside is lumpy at the detail noise's scale, hundreds of metres (the
  // textured base of stratus and nimbostratus; part of the detail, like the erosion:
  // CloudField::base_lift_factor, cloud_density.glsl base_lift_factor).
  double base_relief = 0.0;
  bool stratiform = false;
  Anvil anvil;  // spread 0 except cumulonimbus
};
const CloudTypeTraits& cloud_type_traits(CloudType t);

// A textured base (CloudTypeTraits::base_relief r) lifts the base by r * saturate(kBaseLiftMean
// + D - mean(D)) of the layer's depth where the detail noise reads D: by r * kBaseLiftMean
// where D is at its mean, which is the lift of the light's base-shape field and of the
// homogeneous layer of the diffuse light (CloudField::base_lift, cloud_density.glsl
// base_lift). [BASE_LIFT_MEAN]
inline constexpr double kBaseLiftMean = 0.5;

// All cloud types except None, in enum order.
const std::vector<CloudType>& all_cloud_types();

struct Wind {
  double east_mps = 0.0;
  double north_mps = 0.0;
  bool operator==(const Wind&) const = default;
};

struct CloudLayer {
  CloudType type = CloudType::Cumulus;
  double base_m = 1000.0;   // bottom of the layer, m above the ellipsoid
  double top_m = 2000.0;    // top of the layer, m above the ellipsoid (> base_m)
  double coverage = 0.5;    // fraction of the sky covered, [0, 1]
  double density_scale = 1.0;          // multiplier on microphysical extinction, [0, 10]
  double droplet_diameter_um = 20.0;   // [5, 50]
  Wind wind;                           // m/s, drives the cloud field's drift
  // Where the layer's local coverage comes from: -1, its coverage modulated by the weather
  // map's R channel (weather_map.h, local_coverage); 0-3, the map's layer-coverage channel
  // of that number as it is (forecast weather: weather/forecast_frame.h). Not part of
  // weather files or the protocol's layers.
  int coverage_channel = -1;
  bool operator==(const CloudLayer&) const = default;
};

constexpr int kMaxCloudLayers = 4;

// A layer of type t with every field at the type's defaults (coverage 0.5, no wind).
CloudLayer default_layer(CloudType t);

// Everything the renderer needs to know about weather at one time.
struct Weather {
  std::string name;                // preset name or file name, for logs
  std::vector<CloudLayer> layers;  // at most kMaxCloudLayers, sorted by base altitude
  std::uint32_t map_seed = 1;      // seed of the procedural global weather map
  // Lambertian albedo of the ground, grey, [0, 1] (fresh snow ~0.8, sea ~0.06-0.1); unset:
  // the renderer's default spectrum (model::kGroundAlbedo, 0.14 / 0.12 / 0.08 in rgb).
  std::optional<double> ground_albedo;
  // Horizontal visibility at sea level, m: the meteorological optical range (the distance at
  // which a black object's contrast against the horizon sky falls to 5 %, WMO-No. 8), which
  // sets the haze (aerosol) of the atmosphere (model::atmosphere::aerosol_scale_for_visibility),
  // in [kMinVisibility_m, kMaxVisibility_m]; unset: the model's default aerosol (166 km).
  std::optional<double> visibility_m;
  bool operator==(const Weather&) const = default;
};

// Checks ranges and ordering; returns an empty string when valid, else a one-line
// message naming the offending field (e.g. "layers[1].coverage 1.5 out of range [0, 1]").
// Limits: at most kMaxCloudLayers layers; per layer all values finite, base_m in
// [-500, 20000], top_m in (base_m, 20000] with top_m - base_m >= 10, coverage [0, 1],
// density_scale [0, 10], droplet_diameter_um [5, 50], |wind| <= 150 m/s, type not None;
// layers sorted by base_m and not overlapping in altitude (touching is allowed);
// coverage_channel in [-1, 3]; ground_albedo, when set, finite and in [0, 1]; visibility_m,
// when set, in [kMinVisibility_m, kMaxVisibility_m].
std::string validate(const Weather& w);

// The same checks, with the field ("layers[1].coverage") and the problem ("1.5 out of range
// [0, 1]") apart, so that file loaders can prefix the file name. nullopt when valid.
struct ValidationIssue {
  std::string field;
  std::string problem;
};
std::optional<ValidationIssue> validate_layer(const CloudLayer& layer, int index);
std::optional<ValidationIssue> validate_detail(const Weather& w);

// Limits used by validate (also quoted in docs/WEATHER.md).
constexpr double kMinLayerBase_m = -500.0;
constexpr double kMaxLayerTop_m = 20000.0;
constexpr double kMinLayerThickness_m = 10.0;
constexpr double kMaxDensityScale = 10.0;
constexpr double kMinDropletDiameter_um = 5.0;
constexpr double kMaxDropletDiameter_um = 50.0;
constexpr double kMaxWindSpeed_mps = 150.0;
// Visibility: below 1 km is fog, which the haze of the atmosphere model does not draw (a
// shallow layer, not an exponential aerosol profile); above ~220 km the air is clearer than
// its molecules allow and the aerosol is simply 0.
constexpr double kMinVisibility_m = 1000.0;
constexpr double kMaxVisibility_m = 1.0e6;

}  // namespace cloudsvc::weather
