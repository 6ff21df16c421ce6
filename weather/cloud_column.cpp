// Forecast cloud bands -> renderer layers (cloud_column.h).
#include "weather/cloud_column.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "weather/standard_atmosphere.h"

namespace cloudsvc::weather {

namespace {

bool given(double v) { return std::isfinite(v); }

// A band's layer of type t, or nullopt when the band is clear. Missing altitudes come from
// the type's defaults, keeping its default thickness next to the altitude that is given.
std::optional<CloudLayer> band_layer(CloudType t, const BandValues& band) {
  if (!given(band.cover) || band.cover < kLeastLayerCover) return std::nullopt;
  CloudLayer layer = default_layer(t);
  const double thickness = layer.top_m - layer.base_m;
  layer.coverage = std::clamp(band.cover, 0.0, 1.0);
  if (given(band.base_m) && given(band.top_m)) {
    layer.base_m = std::min(band.base_m, band.top_m);
    layer.top_m = std::max(band.base_m, band.top_m);
  } else if (given(band.base_m)) {
    layer.base_m = band.base_m;
    layer.top_m = band.base_m + thickness;
  } else if (given(band.top_m)) {
    layer.top_m = band.top_m;
    layer.base_m = band.top_m - thickness;
  }
  layer.top_m = std::max(layer.top_m, layer.base_m + kLeastBandThickness_m);
  layer.base_m = std::max(layer.base_m, kMinLayerBase_m);
  layer.top_m = std::min(layer.top_m, kMaxLayerTop_m);
  if (layer.top_m - layer.base_m < kMinLayerThickness_m) return std::nullopt;
  return layer;
}

// Places `layer` in the largest part of its altitude range that no placed layer occupies;
// drops it when that part is thinner than kMinLayerThickness_m.
void place_apart(std::vector<CloudLayer>& placed, CloudLayer layer) {
  std::vector<std::pair<double, double>> taken;
  for (const CloudLayer& p : placed) taken.emplace_back(p.base_m, p.top_m);
  std::sort(taken.begin(), taken.end());
  double best_base = 0.0, best_top = 0.0, cursor = layer.base_m;
  const auto consider = [&](double lo, double hi) {
    if (hi - lo > best_top - best_base) best_base = lo, best_top = hi;
  };
  for (const auto& [lo, hi] : taken) {
    if (hi <= cursor) continue;
    if (lo >= layer.top_m) break;
    consider(cursor, std::min(lo, layer.top_m));
    cursor = std::max(cursor, hi);
  }
  if (cursor < layer.top_m) consider(cursor, layer.top_m);
  if (best_top - best_base < kMinLayerThickness_m) return;
  layer.base_m = best_base;
  layer.top_m = best_top;
  placed.push_back(layer);
}

}  // namespace

CloudColumn blend_columns(const CloudColumn& a, const CloudColumn& b, double w) {
  const auto mix = [w](double x, double y) { return !given(x) ? y : !given(y) ? x : x + (y - x) * w; };
  CloudColumn out;
  out.ground_m = given(a.ground_m) ? a.ground_m : b.ground_m;
  for (int i = 0; i < kColumnBands; ++i) {
    out.bands[i].cover = mix(a.bands[i].cover, b.bands[i].cover);
    out.bands[i].base_m = mix(a.bands[i].base_m, b.bands[i].base_m);
    out.bands[i].top_m = mix(a.bands[i].top_m, b.bands[i].top_m);
  }
  return out;
}

void ColumnAverage::add(const CloudColumn& c, double weight) {
  if (given(c.ground_m)) ground_w_ += weight, ground_ += weight * c.ground_m;
  for (int b = 0; b < kColumnBands; ++b) {
    const BandValues& v = c.bands[b];
    if (!given(v.cover)) continue;
    Sum& s = sums_[b];
    s.w += weight;
    s.cover += weight * v.cover;
    if (v.cover < kLeastLayerCover) continue;
    const double wc = weight * v.cover;
    if (given(v.base_m)) s.wc_base += wc, s.base += wc * v.base_m;
    if (given(v.top_m)) s.wc_top += wc, s.top += wc * v.top_m;
  }
}

CloudColumn ColumnAverage::result() const {
  CloudColumn out;
  if (ground_w_ > 0.0) out.ground_m = ground_ / ground_w_;
  for (int b = 0; b < kColumnBands; ++b) {
    const Sum& s = sums_[b];
    if (s.w <= 0.0) continue;
    out.bands[b].cover = s.cover / s.w;
    if (s.wc_base > 0.0) out.bands[b].base_m = s.base / s.wc_base;
    if (s.wc_top > 0.0) out.bands[b].top_m = s.top / s.wc_top;
  }
  return out;
}

double low_middle_boundary_m() { return standard_pressure_altitude_m(0.8 * kSeaLevelPressure_Pa); }
double middle_high_boundary_m() { return standard_pressure_altitude_m(0.45 * kSeaLevelPressure_Pa); }

void fill_bands_from_profile(CloudColumn& column, std::vector<ProfileSample> profile) {
  profile.erase(std::remove_if(profile.begin(), profile.end(),
                               [](const ProfileSample& s) { return !given(s.altitude_m) || !given(s.cover); }),
                profile.end());
  if (profile.empty()) return;
  std::sort(profile.begin(), profile.end(), [](const ProfileSample& a, const ProfileSample& b) { return a.altitude_m < b.altitude_m; });
  const double bounds[4] = {-1e9, low_middle_boundary_m(), middle_high_boundary_m(), 1e9};
  const CloudBand bands[3] = {CloudBand::Low, CloudBand::Middle, CloudBand::High};
  for (int b = 0; b < 3; ++b) {
    BandValues& band = column[bands[b]];
    if (given(band.cover)) continue;  // the forecast's own band cover comes first
    double cover = 0.0;
    int lowest = -1, highest = -1;
    for (int k = 0; k < static_cast<int>(profile.size()); ++k) {
      const ProfileSample& s = profile[k];
      if (s.altitude_m < bounds[b] || s.altitude_m >= bounds[b + 1]) continue;
      cover = std::max(cover, std::clamp(s.cover, 0.0, 1.0));
      if (s.cover >= kProfileCloudyCover) {
        if (lowest < 0) lowest = k;
        highest = k;
      }
    }
    band.cover = cover;
    if (lowest < 0) continue;
    const double n = static_cast<double>(profile.size());
    const double below = lowest > 0 ? 0.5 * (profile[lowest].altitude_m - profile[lowest - 1].altitude_m) : 0.0;
    const double above = highest + 1 < n ? 0.5 * (profile[highest + 1].altitude_m - profile[highest].altitude_m) : 0.0;
    band.base_m = profile[lowest].altitude_m - below;
    band.top_m = profile[highest].altitude_m + above;
  }
}

std::array<SlotBand, kLayerSlots> slot_bands(const CloudColumn& column) {
  const BandValues& conv = column[CloudBand::Convective];
  const double conv_cover = given(conv.cover) ? conv.cover : 0.0;
  const bool convective = conv_cover >= kLeastLayerCover;
  const bool deep = convective && given(conv.top_m) && conv.top_m >= kDeepConvectionTop_m;
  const bool shallow = convective && !deep;

  // Low cloud: the low band, else the boundary-layer band, else (when the forecast gives
  // no middle or high band either) the total cloud.
  BandValues low = column[CloudBand::Low];
  if (!given(low.cover)) low = column[CloudBand::BoundaryLayer];
  const bool banded = given(column[CloudBand::Middle].cover) || given(column[CloudBand::High].cover);
  if (!given(low.cover) && !banded) low.cover = column[CloudBand::Total].cover;
  if (!given(low.base_m)) low.base_m = column[CloudBand::Total].base_m;  // e.g. cloud base height
  // Shallow convection makes the low cloud cumulus when it is at least half of it (else a
  // deck with embedded cumuli: stratocumulus), and at least as wide as the convective cloud.
  const bool cumuliform = shallow && conv_cover >= kCumulusShareOfLowCloud * (given(low.cover) ? low.cover : 0.0);
  if (shallow) {
    low.cover = std::max(given(low.cover) ? low.cover : 0.0, conv_cover);
    if (!given(low.base_m)) low.base_m = conv.base_m;
    if (!given(low.top_m)) low.top_m = conv.top_m;
  }
  const bool near_ground = given(column.ground_m) && given(low.base_m) &&
                           low.base_m - column.ground_m < kStratusBaseAboveGround_m;

  const BandValues& middle = column[CloudBand::Middle];
  const BandValues& high = column[CloudBand::High];
  const auto sheet_from = [](const BandValues& b, CloudType cellular, CloudType sheet) {
    return given(b.cover) && b.cover >= kSheetCover ? sheet : cellular;
  };
  std::array<SlotBand, kLayerSlots> slots;
  slots[kLowSlot] = {cumuliform ? CloudType::Cumulus : near_ground ? CloudType::Stratus : CloudType::Stratocumulus, low};
  slots[kMiddleSlot] = {sheet_from(middle, CloudType::Altocumulus, CloudType::Altostratus), middle};
  slots[kHighSlot] = {sheet_from(high, CloudType::Cirrus, CloudType::Cirrostratus), high};
  slots[kDeepConvectionSlot] = {CloudType::Cumulonimbus, deep ? conv : BandValues{0.0}};
  return slots;
}

std::vector<CloudLayer> layers_from_slots(const std::array<SlotBand, kLayerSlots>& slots) {
  // Candidates in the order of precedence for equal cover: deep convection, low, middle, high.
  std::vector<CloudLayer> candidates;
  for (int k : {kDeepConvectionSlot, kLowSlot, kMiddleSlot, kHighSlot})
    if (std::optional<CloudLayer> layer = band_layer(slots[k].type, slots[k].band)) {
      layer->coverage_channel = k;
      candidates.push_back(*layer);
    }
  // Where layers overlap, the one covering more of the sky keeps its altitudes (ties: the
  // order above) and the others move into the free part of their range.
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const CloudLayer& a, const CloudLayer& b) { return a.coverage > b.coverage; });
  std::vector<CloudLayer> placed;
  for (const CloudLayer& layer : candidates)
    if (static_cast<int>(placed.size()) < kMaxCloudLayers) place_apart(placed, layer);
  std::sort(placed.begin(), placed.end(), [](const CloudLayer& a, const CloudLayer& b) { return a.base_m < b.base_m; });
  return placed;
}

std::vector<CloudLayer> layers_from_column(const CloudColumn& column) { return layers_from_slots(slot_bands(column)); }

std::array<float, kLayerSlots> slot_covers(const CloudColumn& column) {
  const std::array<SlotBand, kLayerSlots> slots = slot_bands(column);
  std::array<float, kLayerSlots> covers{};
  for (int k = 0; k < kLayerSlots; ++k) {
    const double c = slots[k].band.cover;
    covers[k] = given(c) ? static_cast<float>(std::clamp(c, 0.0, 1.0)) : 0.0f;
  }
  return covers;
}

}  // namespace cloudsvc::weather
