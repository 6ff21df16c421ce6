// CIGI cloud layers -> the renderer's weather (cigi_weather.h).
#include "protocol/cigi/cigi_weather.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

#include "common/parallel_for.h"
#include "weather/cloud_water.h"
#include "weather/sphere_geometry.h"

namespace cloudsvc::cigi {
namespace {

constexpr double kMinThickness_m = 10.0;  // as weather::validate

// The layer that defines layer id k's altitudes: global, else the nearest region's.
std::optional<WeatherControl> defining_layer(const IgState& s, int k, double lat, double lon) {
  if (s.global_layers()[static_cast<std::size_t>(k)]) return s.global_layers()[static_cast<std::size_t>(k)];
  std::optional<WeatherControl> best;
  double best_d = 0.0;
  for (const auto& [id, region] : s.regions()) {
    const auto& layer = region.layers[static_cast<std::size_t>(k)];
    if (!layer || region.control.state != 1) continue;
    const double d = weather::surface_distance_m(lat, lon, region.control.lat_deg, region.control.lon_deg);
    if (!best || d < best_d) best = layer, best_d = d;
  }
  return best;
}

// Shortest fixed-point text that reads back to v ("300", "0.5", "1000000").
template <class T>
std::string shortest_text(T v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  return std::string(buf, r.ptr);
}

const char* layer_name(int slot) {
  static constexpr const char* kNames[] = {"layer 1", "layer 2", "layer 3"};
  return kNames[slot];
}

// The layer's density scale: from the host's water content (Weather Control's aerosol
// concentration, g/m^3) in the type's droplets where one is given (> 0), else the type's
// default; above weather::kMaxDensityScale drawn at it, with a note.
double layer_density_scale(const WeatherControl& w, const weather::CloudTypeTraits& traits, int slot,
                           std::vector<std::string>& notes) {
  if (!(w.aerosol_gpm3 > 0.0f)) return traits.default_density_scale;
  const double d_um = traits.default_droplet_diameter_um;
  const double s = weather::density_scale_for_water_content(w.aerosol_gpm3, d_um);
  if (s <= weather::kMaxDensityScale) return s;
  const double drawn = weather::kMaxDensityScale * weather::water_content_of_n0_droplets_g_m3(d_um);
  notes.push_back(std::string(layer_name(slot)) + ": water content " + shortest_text(w.aerosol_gpm3) + " g/m^3 drawn as " +
                  shortest_text(static_cast<float>(drawn)) + " g/m^3 (the most drawn in its droplets)");
  return weather::kMaxDensityScale;
}

weather::CloudLayer renderer_layer(const WeatherControl& w, int slot, std::vector<std::string>& notes) {
  weather::CloudLayer l;
  l.type = static_cast<weather::CloudType>(w.cloud_type);
  l.base_m = w.base_elevation_m;
  l.top_m = static_cast<double>(w.base_elevation_m) + std::max(static_cast<double>(w.thickness_m), kMinThickness_m);
  l.coverage = std::clamp(w.coverage_pct / 100.0, 0.0, 1.0);  // not read: the layer reads its channel
  l.coverage_channel = slot;
  const weather::CloudTypeTraits& traits = weather::cloud_type_traits(l.type);
  l.density_scale = layer_density_scale(w, traits, slot, notes);
  l.droplet_diameter_um = traits.default_droplet_diameter_um;
  // CIGI gives the direction the wind blows from, clockwise from north.
  const double from = w.wind_direction_deg * weather::kRadPerDeg;
  l.wind = {-w.wind_horizontal_mps * std::sin(from), -w.wind_horizontal_mps * std::cos(from)};
  return l;
}

}  // namespace

namespace {

// A region's rounded rectangle on the tangent plane at its centre (gnomonic), with what
// every point's distance to it needs computed once.
struct RegionFrame {
  std::array<double, 3> centre, east, north;  // unit vectors (ECEF directions)
  double cos_rot = 1.0, sin_rot = 0.0;        // its x axis, clockwise from north
  double half_x_m = 0.0, half_y_m = 0.0, radius_m = 0.0, perimeter_m = 0.0;

  explicit RegionFrame(const EnvironmentalRegionControl& r) {
    centre = weather::unit_vector(r.lat_deg, r.lon_deg);
    const double lat0 = r.lat_deg * weather::kRadPerDeg, lon0 = r.lon_deg * weather::kRadPerDeg;
    east = {-std::sin(lon0), std::cos(lon0), 0.0};
    north = {-std::sin(lat0) * std::cos(lon0), -std::sin(lat0) * std::sin(lon0), std::cos(lat0)};
    const double rot = r.rotation_deg * weather::kRadPerDeg;
    cos_rot = std::cos(rot);
    sin_rot = std::sin(rot);
    radius_m = std::min<double>(r.corner_radius_m, 0.5 * std::min(r.size_x_m, r.size_y_m));
    half_x_m = 0.5 * r.size_x_m;
    half_y_m = 0.5 * r.size_y_m;
    perimeter_m = r.transition_perimeter_m > 0.0f ? r.transition_perimeter_m : 0.0;
  }

  // The signed distance (m, on the plane, negative inside) from the rectangle to the point
  // of unit vector p, and the cosine of the angle between p and the centre; none on the far
  // side (no tangent-plane point).
  struct Point {
    double outside_m, cos_angle;
  };
  std::optional<Point> at(const std::array<double, 3>& p) const {
    const double cos_angle = centre[0] * p[0] + centre[1] * p[1] + centre[2] * p[2];
    if (cos_angle <= 1e-6) return std::nullopt;
    const double scale = weather::kMeanEarthRadius_m / cos_angle;
    const double e = scale * (east[0] * p[0] + east[1] * p[1] + east[2] * p[2]);
    const double n = scale * (north[0] * p[0] + north[1] * p[1] + north[2] * p[2]);
    const double x = n * cos_rot + e * sin_rot, y = -n * sin_rot + e * cos_rot;
    const double qx = std::abs(x) - (half_x_m - radius_m), qy = std::abs(y) - (half_y_m - radius_m);
    return Point{std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0) - radius_m, cos_angle};
  }

  // region_weight at p.
  double weight(const std::array<double, 3>& p) const {
    const std::optional<Point> q = at(p);
    if (!q) return 0.0;
    if (q->outside_m <= 0.0) return 1.0;
    if (!(perimeter_m > 0.0) || q->outside_m >= perimeter_m) return 0.0;
    return 1.0 - q->outside_m / perimeter_m;
  }
};

}  // namespace

double region_weight(const EnvironmentalRegionControl& r, double lat_deg, double lon_deg) {
  if (r.state != 1) return 0.0;
  return RegionFrame(r).weight(weather::unit_vector(lat_deg, lon_deg));
}

CigiVisibility cigi_visibility(const IgState& state) {
  CigiVisibility out;
  if (!state.atmosphere()) return out;
  const float sent = state.atmosphere()->visibility_m;  // m, finite and >= 0 (cigi_checks)
  const double drawn = std::clamp(static_cast<double>(sent), weather::kMinVisibility_m, weather::kMaxVisibility_m);
  out.visibility_m = drawn;
  if (drawn != static_cast<double>(sent))
    out.note = "Atmosphere Control: visibility " + shortest_text(sent) + " m drawn as " + shortest_text(drawn) + " m" +
               (drawn > sent ? " (fog is not drawn)" : " (the largest drawn)");
  return out;
}

CloudLayerSet defining_layers(const IgState& state, double near_lat_deg, double near_lon_deg) {
  CloudLayerSet out;
  for (int k = 0; k < 3; ++k) out[static_cast<std::size_t>(k)] = defining_layer(state, k, near_lat_deg, near_lon_deg);
  return out;
}

CigiWeather cigi_weather(const IgState& state, double near_lat_deg, double near_lon_deg, int width, int height) {
  CigiWeather out;
  out.weather.name = "CIGI";
  out.weather.visibility_m = cigi_visibility(state).visibility_m;
  // Layers 1..3, each from its defining Weather Control. The thickest keep their altitudes;
  // a thinner one keeps the largest part of its own that no thicker one holds.
  std::vector<weather::CloudLayer> candidates;
  const CloudLayerSet defining = defining_layers(state, near_lat_deg, near_lon_deg);
  for (int k = 0; k < 3; ++k)
    if (const auto& w = defining[static_cast<std::size_t>(k)]) candidates.push_back(renderer_layer(*w, k, out.notes));
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.top_m - a.base_m > b.top_m - b.base_m; });
  std::vector<weather::CloudLayer> layers;
  for (weather::CloudLayer l : candidates) {
    std::vector<std::pair<double, double>> free{{l.base_m, l.top_m}};  // its parts no kept layer holds
    std::string within;
    for (const weather::CloudLayer& k : layers) {
      std::vector<std::pair<double, double>> next;
      for (const auto& [b, t] : free) {
        if (k.top_m <= b || k.base_m >= t) {
          next.push_back({b, t});
          continue;
        }
        within = layer_name(k.coverage_channel);
        if (b < k.base_m) next.push_back({b, k.base_m});
        if (k.top_m < t) next.push_back({k.top_m, t});
      }
      free = next;
    }
    const auto largest = std::max_element(free.begin(), free.end(), [](const auto& a, const auto& b) {
      return a.second - a.first < b.second - b.first;
    });
    if (largest == free.end() || largest->second - largest->first < kMinThickness_m) {
      out.notes.push_back(std::string(layer_name(l.coverage_channel)) + " lies within " + within + ": not drawn");
      continue;
    }
    if (largest->first != l.base_m || largest->second != l.top_m) {
      l.base_m = largest->first;
      l.top_m = largest->second;
      out.notes.push_back(std::string(layer_name(l.coverage_channel)) + " overlaps " + within + ": drawn from " +
                          std::to_string(static_cast<int>(std::lround(l.base_m))) + " to " +
                          std::to_string(static_cast<int>(std::lround(l.top_m))) + " m");
    }
    layers.push_back(l);
  }
  std::sort(layers.begin(), layers.end(), [](const auto& a, const auto& b) { return a.base_m < b.base_m; });
  out.weather.layers = layers;

  // The map: each slot's coverage at every texel.
  weather::WeatherMap& m = out.map;
  m.width = width;
  m.height = height;
  const std::size_t texels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  m.rgba.assign(texels * 4, 0.5f);
  for (std::size_t n = 0; n < texels; ++n) m.rgba[4 * n + 3] = 0.0f;
  m.layer_coverage.assign(texels * 4, 0.0f);
  std::array<double, 3> global{};
  for (int k = 0; k < 3; ++k)
    if (const auto& g = state.global_layers()[static_cast<std::size_t>(k)]) global[static_cast<std::size_t>(k)] = g->coverage_pct / 100.0;
  // Regions in id order (a later region's weather lies over an earlier one's), each with the
  // angle beyond which it weighs nothing (half diagonal plus perimeter) widened by a texel.
  const double dlat = 180.0 / height, dlon = 360.0 / width;
  const double texel_rad = std::max(dlat, dlon) * weather::kRadPerDeg;  // a texel's reach
  struct Reach {
    const Region* region;
    RegionFrame frame;
    double cos_near;   // of the angle within which a texel's centre lies when the texel may meet it
    double feature_m;  // its smaller side: texels near it are sampled finer than this
  };
  std::vector<Reach> regions;
  for (const auto& [id, region] : state.regions()) {
    const EnvironmentalRegionControl& c = region.control;
    if (c.state != 1) continue;
    const double reach_m = 0.5 * std::hypot(c.size_x_m, c.size_y_m) + c.transition_perimeter_m;
    regions.push_back({&region, RegionFrame(c), std::cos(std::min(reach_m / weather::kMeanEarthRadius_m + texel_rad, 3.14159)),
                       std::max(1.0, static_cast<double>(std::min(c.size_x_m, c.size_y_m)))});
  }
  // Which regions touch a texel (centre p, half diagonal half_diag_m on the ground), and how
  // finely it must be sampled for them: a region that covers the whole texel (weight 1
  // throughout) needs one sample, one whose edge or perimeter crosses it n x n with n such
  // that the region's smaller side spans at least 32 samples (4 <= n <= 64), so that a region
  // smaller than a few texels keeps its share of the texels' cover (within a few per cent)
  // though not its shape. The plane stretches ground distances by up to 1 / cos^2 of the
  // angle from the centre, so the texel's reach on the plane is taken that much larger.
  const double texel_m = weather::kMeanEarthRadius_m * dlat * weather::kRadPerDeg;  // a texel's side along a meridian, m
  // The regions are at most IgState::kMaxRegions, so a texel's set is a bit mask of their
  // indices (ascending bits: id order).
  static_assert(IgState::kMaxRegions <= 64, "a texel's regions are a 64-bit mask");
  const auto touching = [&](const std::array<double, 3>& p, double half_diag_m, std::uint64_t& out) {
    out = 0;
    int n = 1;
    for (std::size_t k = 0; k < regions.size(); ++k) {
      const Reach& r = regions[k];
      if (p[0] * r.frame.centre[0] + p[1] * r.frame.centre[1] + p[2] * r.frame.centre[2] <= r.cos_near) continue;
      const std::optional<RegionFrame::Point> q = r.frame.at(p);
      const bool edge_crosses =
          !q || q->cos_angle < 0.1 || std::abs(q->outside_m - 0.5 * r.frame.perimeter_m) <=
                                          0.5 * r.frame.perimeter_m + half_diag_m / (q->cos_angle * q->cos_angle);
      if (q && !edge_crosses && q->outside_m > 0.0) continue;  // beyond its perimeter: weight 0 throughout
      out |= std::uint64_t{1} << k;
      if (edge_crosses) n = std::max(n, std::clamp(static_cast<int>(std::ceil(32.0 * texel_m / r.feature_m)), 4, 64));
    }
    return n;
  };
  // At most kMaxRegionSamples region weights per map (about a second on 2 cores): a datagram
  // of regions thinner than a texel and as long as the Earth is wide must not stall the IG.
  // Beyond it every texel's samples are cut in proportion; such regions' share of a texel's
  // cover is then a few of its samples' (their shape was not drawn in any case).
  constexpr double kMaxRegionSamples = 1 << 26;
  // Each texel is classified once: the regions touching it and the n of its n x n samples.
  std::vector<std::uint64_t> near_mask(texels, 0);
  std::vector<int> planned_samples(texels, 0);
  std::vector<double> row_cost(static_cast<std::size_t>(height), 0.0);
  parallel_for(height, kAllThreads, [&](int j) {
    const double lat = -90.0 + (j + 0.5) * dlat;
    const double half_diag_m = 0.5 * std::hypot(texel_m, texel_m * std::cos(lat * weather::kRadPerDeg) * dlon / dlat);
    const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(width);
    for (int i = 0; i < width; ++i) {
      const std::size_t t = row + static_cast<std::size_t>(i);
      const int n = touching(weather::unit_vector(lat, -180.0 + (i + 0.5) * dlon), half_diag_m, near_mask[t]);
      if (near_mask[t] == 0) continue;
      planned_samples[t] = n;
      row_cost[static_cast<std::size_t>(j)] += static_cast<double>(n) * n * std::popcount(near_mask[t]);
    }
  });
  double cost = 0.0;
  for (const double c : row_cost) cost += c;
  const double sample_scale = cost > kMaxRegionSamples ? std::sqrt(kMaxRegionSamples / cost) : 1.0;
  out.region_samples = static_cast<std::uint64_t>(std::min(cost, kMaxRegionSamples));
  // A texel's cover: the global cover with the regions that touch it laid over it, at its
  // centre or as the mean over its n x n samples.
  const auto cover_at = [&](const std::array<double, 3>& p, std::uint64_t near) {
    std::array<double, 3> cover = global;
    for (; near != 0; near &= near - 1) {
      const Reach* r = &regions[static_cast<std::size_t>(std::countr_zero(near))];
      const double w = r->frame.weight(p);
      if (w <= 0.0) continue;
      for (std::size_t k = 0; k < 3; ++k) {
        const auto& inside = r->region->layers[k];
        cover[k] = (1.0 - w) * cover[k] + w * (inside ? inside->coverage_pct / 100.0 : 0.0);
      }
    }
    return cover;
  };
  parallel_for(height, kAllThreads, [&](int j) {
    const double lat = -90.0 + (j + 0.5) * dlat;
    const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(width);
    for (int i = 0; i < width; ++i) {
      const double lon = -180.0 + (i + 0.5) * dlon;
      const std::size_t t = row + static_cast<std::size_t>(i);
      const std::uint64_t near = near_mask[t];
      std::array<double, 3> cover = global;
      if (near != 0) {
        const int n = std::max(1, static_cast<int>(planned_samples[t] * sample_scale));
        cover = {0.0, 0.0, 0.0};
        for (int a = 0; a < n; ++a)
          for (int b = 0; b < n; ++b) {
            const std::array<double, 3> c =
                cover_at(weather::unit_vector(lat + ((a + 0.5) / n - 0.5) * dlat, lon + ((b + 0.5) / n - 0.5) * dlon), near);
            for (std::size_t k = 0; k < 3; ++k) cover[k] += c[k] / (n * n);
          }
      }
      float* out_texel = &m.layer_coverage[t * 4];
      for (std::size_t k = 0; k < 3; ++k) out_texel[k] = static_cast<float>(std::clamp(cover[k], 0.0, 1.0));
    }
  });
  return out;
}

}  // namespace cloudsvc::cigi
