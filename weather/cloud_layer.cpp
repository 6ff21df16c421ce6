// Cloud types: names, typical traits per type, and validation of a Weather.
//
// Altitudes follow the WMO International Cloud Atlas étages for mid-latitudes (low: base
// below 2 km; middle: 2-7 km; high: 5-13 km). Droplet diameters and water contents are
// typical, order-of-magnitude values from the cloud-physics literature (stratiform liquid
// clouds: Miles, Verlinde & Clothiaux 2000, J. Atmos. Sci. 57, effective radii 5-10 um,
// LWC 0.1-0.5 g/m^3); Ford 2024 §3.2.3 gives 5-50 um as the range of cloud droplet
// diameters, typically near 10 um. Height-profile shapes follow Schneider's per-type
// height gradients (Schneider 2015; Ford 2024 §2.1 and §4.2.1: stratus low and thin,
// cumulus over a broader altitude range with rounded tops).
//
// default_density_scale = LWC / LWC_N0(d), LWC_N0(d) = 4/3 pi (d/2)^3 rho_w N0 with
// N0 = 300 cm^-3 and rho_w = 1e6 g/m^3 (see cloud_layer.h): e.g. cumulus, d = 20 um,
// LWC_N0 = 1.26 g/m^3, typical LWC 0.5 g/m^3 -> 0.40, giving sigma_t = 0.075 /m (mean free
// path 13 m; Bouthors et al. 2008 §3.1: several to ~20 m for stratiform clouds).
#include "weather/cloud_layer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace cloudsvc::weather {
namespace {

struct TypeEntry {
  CloudType type;
  std::string_view name;
  std::string_view alias;  // WMO abbreviation, lower case
};

constexpr std::array<TypeEntry, 11> kTypes = {{
    {CloudType::None, "none", ""},
    {CloudType::Altocumulus, "altocumulus", "ac"},
    {CloudType::Altostratus, "altostratus", "as"},
    {CloudType::Cirrocumulus, "cirrocumulus", "cc"},
    {CloudType::Cirrostratus, "cirrostratus", "cs"},
    {CloudType::Cirrus, "cirrus", "ci"},
    {CloudType::Cumulonimbus, "cumulonimbus", "cb"},
    {CloudType::Cumulus, "cumulus", "cu"},
    {CloudType::Nimbostratus, "nimbostratus", "ns"},
    {CloudType::Stratocumulus, "stratocumulus", "sc"},
    {CloudType::Stratus, "stratus", "st"},
}};

CloudTypeTraits make_traits(HeightProfile profile, double base_m, double top_m,
                            double droplet_um, double density_scale, double noise_scale_m,
                            bool stratiform, double noise_vertical_scale = 1.0, Anvil anvil = {}) {
  CloudTypeTraits t;
  t.profile = profile;
  t.default_base_m = base_m;
  t.default_top_m = top_m;
  t.default_droplet_diameter_um = droplet_um;
  t.default_density_scale = density_scale;
  t.noise_scale_m = noise_scale_m;
  t.stratiform = stratiform;
  t.noise_vertical_scale = noise_vertical_scale;
  t.anvil = anvil;
  return t;
}

CloudTypeTraits with_strands(CloudTypeTraits t, double strand_ratio) {
  t.strand_ratio = strand_ratio;
  return t;
}

CloudTypeTraits with_base_relief(CloudTypeTraits t, double base_relief) {
  t.base_relief = base_relief;
  return t;
}

// Indexed by the CIGI number (CloudType value).
const std::array<CloudTypeTraits, 11>& traits_table() {
  static const std::array<CloudTypeTraits, 11> table = {
      // None: no cloud; zero density so that a stray None layer draws nothing.
      make_traits({0.1f, 0.3f, 0.0f, 0.5f}, 1000, 2000, 20, 0.0, 8000, true),
      // Altocumulus: mid-level (2-7 km) sheet of small rounded elements, thin (0.2-1 km).
      // Liquid, small droplets (d ~12 um), LWC ~0.2 g/m^3 -> 0.2 / 0.27 = 0.74. Short
      // noise period: elements ~0.5-1 km. Strongly eroded edges.
      make_traits({0.2f, 0.4f, 0.0f, 0.6f}, 3000, 3800, 12, 0.74, 6000, true),
      // Altostratus: mid-level grey sheet, 1-3 km thick, mostly uniform, mixed phase
      // (treated as liquid), d ~14 um, LWC ~0.2 g/m^3 -> 0.2 / 0.43 = 0.46. Long period.
      make_traits({0.15f, 0.2f, 0.0f, 0.3f}, 3000, 5000, 14, 0.46, 30000, true),
      // Cirrocumulus: high (7-8 km) thin sheet of tiny ice elements. Ice is modelled with
      // the droplet phase function for now; d = 40 um stands in for the crystal size.
      // IWC ~0.02 g/m^3 over LWC_N0(40 um) = 10 g/m^3 -> 0.002 (ice crystal number
      // densities are ~0.1-1 cm^-3, three orders of magnitude below N0).
      make_traits({0.3f, 0.3f, 0.0f, 0.7f}, 7000, 7600, 40, 0.002, 4000, true),
      // Cirrostratus: high (8-10 km) transparent ice veil, uniform. Droplet phase
      // function for now, d = 50 um (range limit; crystals are larger). IWC ~0.01 g/m^3
      // over LWC_N0(50 um) = 19.6 g/m^3 -> 0.0005.
      make_traits({0.2f, 0.3f, 0.0f, 0.3f}, 8000, 9500, 50, 0.0005, 50000, true),
      // Cirrus: high (9-10 km) fibrous ice wisps. Droplet phase function for now,
      // d = 50 um, IWC ~0.01 g/m^3 -> 0.0005 (sigma_t ~ 6e-4 /m: optical depth ~0.6
      // through 1 km at full density). Heavy erosion for wispy edges. Strands east-west
      // (fibratus: filaments tens of km long, ~1 km wide, WMO International Cloud Atlas,
      // along the upper-level westerlies): the shape noise 6x finer along the Earth's axis.
      with_strands(make_traits({0.2f, 0.4f, 0.0f, 0.9f}, 9000, 10000, 50, 0.0005, 40000, true), 6.0),
      // Cumulonimbus: convective tower from a low base (~1 km) to the tropopause
      // (~12 km); large droplets (d ~30 um) and high LWC (~1.5 g/m^3) -> 1.5 / 4.24 = 0.35
      // (sigma_t 0.15 /m). Sharp base, short top ramp under the flat top. Dense from base
      // to top (a profile growing with height, thresholded by coverage, left only
      // floating upper blobs). Shape noise stretched 2x vertically for towers; period
      // 24 km: cells ~6 km across.
      // Anvil (weather::Anvil): a shield over height fractions 0.78-0.96 of the layer (2 km
      // of the default 11 km depth) spreading the cells' coverage c to 1 - (1 - c)^5 (0.35 ->
      // 0.88) at 0.15 of the tower's extinction.
      make_traits({0.03f, 0.1f, 0.0f, 0.5f}, 1000, 12000, 30, 0.35, 24000, false, 0.5, {4.0f, 0.78f, 0.96f, 0.15f}),
      // Cumulus: fair-weather convective cloud, base ~1-1.5 km, 1-2 km deep. Flat base
      // (small bottom ramp), rounded top (large top ramp); d ~20 um, LWC ~0.5 g/m^3 ->
      // 0.5 / 1.26 = 0.40. Cells ~1-2 km.
      // Shape noise stretched 1.5x vertically: cells are about as tall as wide.
      make_traits({0.05f, 0.6f, 0.0f, 0.6f}, 1200, 2600, 20, 0.40, 8000, false, 1.0 / 1.5),
      // Nimbostratus: thick (2-5 km) precipitating grey layer from a low base; d ~18 um,
      // LWC ~0.5 g/m^3 -> 0.5 / 0.92 = 0.55. Nearly uniform, little erosion. A ragged base
      // (pannus under it, WMO International Cloud Atlas): raised by up to 6 % of the depth
      // (200 m of the default 3.4 km) where the detail noise is high.
      with_base_relief(make_traits({0.1f, 0.2f, 0.0f, 0.15f}, 600, 4000, 18, 0.55, 30000, true), 0.06),
      // Stratocumulus: low (0.6-2 km) lumpy sheet, 0.2-0.8 km thick; d ~16 um, LWC
      // ~0.35 g/m^3 -> 0.35 / 0.64 = 0.54. Cells ~1-3 km.
      make_traits({0.15f, 0.3f, 0.0f, 0.35f}, 1200, 1800, 16, 0.54, 12000, true),
      // Stratus: low (0.1-0.6 km base), thin (0.2-0.5 km), a uniform grey sheet; small
      // droplets (d ~12 um), LWC ~0.25 g/m^3 -> 0.25 / 0.27 = 0.92. Little erosion. Its base
      // is not a plane: raised by up to 20 % of the depth (100 m of the default 500 m) where
      // the detail noise is high, a lumpy, textured underside (stratus undulatus, fractus).
      with_base_relief(make_traits({0.1f, 0.15f, 0.0f, 0.2f}, 400, 900, 12, 0.92, 20000, true), 0.2),
  };
  return table;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Compact number for messages: 1.5, 1000, 1e+30, nan.
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string layer_field(int index, const char* field) {
  return "layers[" + std::to_string(index) + "]." + field;
}

std::optional<ValidationIssue> check_range(int index, const char* field, double v, double lo,
                                           double hi) {
  if (!std::isfinite(v)) return ValidationIssue{layer_field(index, field), num(v) + " is not finite"};
  if (v < lo || v > hi) {
    return ValidationIssue{layer_field(index, field),
                           num(v) + " out of range [" + num(lo) + ", " + num(hi) + "]"};
  }
  return std::nullopt;
}

std::string span(const CloudLayer& l) { return num(l.base_m) + " to " + num(l.top_m) + " m"; }

}  // namespace

std::string_view cloud_type_name(CloudType t) {
  for (const TypeEntry& e : kTypes) {
    if (e.type == t) return e.name;
  }
  return "unknown";
}

std::optional<CloudType> cloud_type_from_name(std::string_view name) {
  const std::string n = lower(name);
  for (const TypeEntry& e : kTypes) {
    if (n == e.name || (!e.alias.empty() && n == e.alias)) return e.type;
  }
  return std::nullopt;
}

float height_profile(const HeightProfile& p, float x) {
  if (!(x > 0.0f && x < 1.0f)) return 0.0f;
  const auto smoothstep = [](float e0, float e1, float v) {
    const float t = std::clamp((v - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
  };
  const float bottom = smoothstep(0.0f, std::max(p.bottom_ramp, 1e-3f), x);
  const float top = 1.0f - smoothstep(1.0f - std::max(p.top_ramp, 1e-3f), 1.0f, x);
  return bottom * top * (1.0f + (x - 1.0f) * p.top_weight);  // mix(1, x, top_weight)
}

float type_depth_fraction(float t, bool stratiform) {
  if (stratiform) return 1.0f;
  if (!std::isfinite(t)) t = 0.5f;  // neutral
  return std::clamp(0.5f + t, 0.3f, 1.0f);
}

float type_height_profile(const HeightProfile& p, bool stratiform, float f, float t) {
  const float fv = type_depth_fraction(t, stratiform);
  if (!(f <= fv)) return 0.0f;
  return height_profile(p, f / fv);
}

const CloudTypeTraits& cloud_type_traits(CloudType t) {
  const int i = static_cast<int>(t);
  const auto& table = traits_table();
  return table[(i >= 0 && i < static_cast<int>(table.size())) ? i : 0];
}

const std::vector<CloudType>& all_cloud_types() {
  static const std::vector<CloudType> types = [] {
    std::vector<CloudType> v;
    for (const TypeEntry& e : kTypes) {
      if (e.type != CloudType::None) v.push_back(e.type);
    }
    return v;
  }();
  return types;
}

CloudLayer default_layer(CloudType t) {
  const CloudTypeTraits& tr = cloud_type_traits(t);
  CloudLayer l;
  l.type = t;
  l.base_m = tr.default_base_m;
  l.top_m = tr.default_top_m;
  l.coverage = 0.5;
  l.density_scale = tr.default_density_scale;
  l.droplet_diameter_um = tr.default_droplet_diameter_um;
  return l;
}

std::optional<ValidationIssue> validate_layer(const CloudLayer& l, int i) {
  const int type_number = static_cast<int>(l.type);
  if (l.type == CloudType::None) return ValidationIssue{layer_field(i, "type"), "must not be none"};
  if (type_number < 1 || type_number > 10) {
    return ValidationIssue{layer_field(i, "type"),
                           "unknown cloud type number " + std::to_string(type_number)};
  }
  if (auto e = check_range(i, "base_m", l.base_m, kMinLayerBase_m, kMaxLayerTop_m)) return e;
  if (!std::isfinite(l.top_m)) return ValidationIssue{layer_field(i, "top_m"), num(l.top_m) + " is not finite"};
  if (l.top_m <= l.base_m) {
    return ValidationIssue{layer_field(i, "top_m"), "must be greater than base_m (" +
                                                        num(l.base_m) + "), got " + num(l.top_m)};
  }
  if (l.top_m > kMaxLayerTop_m) {
    return ValidationIssue{layer_field(i, "top_m"),
                           num(l.top_m) + " out of range (base_m, " + num(kMaxLayerTop_m) + "]"};
  }
  if (l.top_m - l.base_m < kMinLayerThickness_m) {
    return ValidationIssue{layer_field(i, "top_m"),
                           "layer is " + num(l.top_m - l.base_m) + " m thick, at least " +
                               num(kMinLayerThickness_m) + " m required"};
  }
  if (auto e = check_range(i, "coverage", l.coverage, 0.0, 1.0)) return e;
  if (auto e = check_range(i, "density_scale", l.density_scale, 0.0, kMaxDensityScale)) return e;
  if (auto e = check_range(i, "droplet_diameter_um", l.droplet_diameter_um,
                           kMinDropletDiameter_um, kMaxDropletDiameter_um)) {
    return e;
  }
  if (!std::isfinite(l.wind.east_mps) || !std::isfinite(l.wind.north_mps)) {
    return ValidationIssue{layer_field(i, "wind_mps"), std::string("[") + num(l.wind.east_mps) + ", " +
                                                           num(l.wind.north_mps) +
                                                           "] is not finite"};
  }
  const double speed = std::hypot(l.wind.east_mps, l.wind.north_mps);
  if (speed > kMaxWindSpeed_mps) {
    return ValidationIssue{layer_field(i, "wind_mps"), "speed " + num(speed) + " m/s exceeds " +
                                                           num(kMaxWindSpeed_mps) + " m/s"};
  }
  if (l.coverage_channel < -1 || l.coverage_channel > 3)
    return ValidationIssue{layer_field(i, "coverage_channel"), std::to_string(l.coverage_channel) + " out of range [-1, 3]"};
  return std::nullopt;
}

std::optional<ValidationIssue> validate_detail(const Weather& w) {
  if (w.ground_albedo && !(*w.ground_albedo >= 0.0 && *w.ground_albedo <= 1.0))
    return ValidationIssue{"ground_albedo", num(*w.ground_albedo) + " out of range [0, 1]"};
  if (w.visibility_m && !(*w.visibility_m >= kMinVisibility_m && *w.visibility_m <= kMaxVisibility_m))
    return ValidationIssue{"visibility_m", num(*w.visibility_m) + " out of range [" + num(kMinVisibility_m) + ", " +
                                               num(kMaxVisibility_m) + "]" +
                                               (*w.visibility_m < kMinVisibility_m ? " (below 1000 m is fog, not drawn)" : "")};
  const int n = static_cast<int>(w.layers.size());
  if (n > kMaxCloudLayers) {
    return ValidationIssue{"layers", std::to_string(n) + " layers, at most " +
                                         std::to_string(kMaxCloudLayers) + " allowed"};
  }
  for (int i = 0; i < n; ++i) {
    if (auto e = validate_layer(w.layers[i], i)) return e;
  }
  for (int i = 1; i < n; ++i) {
    if (w.layers[i].base_m < w.layers[i - 1].base_m) {
      return ValidationIssue{layer_field(i, "base_m"),
                             num(w.layers[i].base_m) + " is below layers[" +
                                 std::to_string(i - 1) + "].base_m (" +
                                 num(w.layers[i - 1].base_m) + "): layers must be sorted by base"};
    }
  }
  // Sorted by base, so any overlap shows up between neighbours.
  for (int i = 1; i < n; ++i) {
    if (w.layers[i].base_m < w.layers[i - 1].top_m) {
      return ValidationIssue{"layers[" + std::to_string(i) + "]",
                             std::string("(") + span(w.layers[i]) + ") overlaps layers[" +
                                 std::to_string(i - 1) + "] (" + span(w.layers[i - 1]) + ")"};
    }
  }
  return std::nullopt;
}

std::string validate(const Weather& w) {
  const auto issue = validate_detail(w);
  return issue ? issue->field + " " + issue->problem : std::string();
}

}  // namespace cloudsvc::weather
