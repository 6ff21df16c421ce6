#include "weather/weather_timeline.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace cloudsvc::weather {

namespace {

// resample_tile into a grid of 4 values per texel (WeatherMap::rgba or layer_coverage).
void resample_into(std::vector<float>& grid, int width, int height, const MapTile& t, const int (&slot)[4]) {
  if (width <= 0 || height <= 0) return;
  const int nch = tile_value_count(t.channels, t.layer_channels);
  const double dlat = (t.lat_max_deg - t.lat_min_deg) / t.height;
  const double dlon = (t.lon_max_deg - t.lon_min_deg) / t.width;
  auto tile_value = [&](int col, int row, int s) {
    col = std::clamp(col, 0, t.width - 1);
    row = std::clamp(row, 0, t.height - 1);
    return t.data[(static_cast<std::size_t>(row) * t.width + col) * nch + s];
  };
  for (int j = 0; j < height; ++j) {
    const double lat = -90.0 + (j + 0.5) * 180.0 / height;
    if (lat < t.lat_min_deg || lat > t.lat_max_deg) continue;
    const double y = (lat - t.lat_min_deg) / dlat - 0.5;
    const int r0 = static_cast<int>(std::floor(y));
    const double fy = y - r0;
    for (int i = 0; i < width; ++i) {
      double lon = -180.0 + (i + 0.5) * 360.0 / width;
      if (lon < t.lon_min_deg) lon += 360.0;  // tiles crossing the antimeridian
      if (lon < t.lon_min_deg || lon > t.lon_max_deg) continue;
      const double x = (lon - t.lon_min_deg) / dlon - 0.5;
      const int c0 = static_cast<int>(std::floor(x));
      const double fx = x - c0;
      float* px = &grid[(static_cast<std::size_t>(j) * width + i) * 4];
      for (int k = 0; k < 4; ++k) {
        if (slot[k] == kResampleOne) px[k] = 1.0f;
        if (slot[k] < 0) continue;
        const double a = tile_value(c0, r0, slot[k]) * (1 - fx) + tile_value(c0 + 1, r0, slot[k]) * fx;
        const double b = tile_value(c0, r0 + 1, slot[k]) * (1 - fx) + tile_value(c0 + 1, r0 + 1, slot[k]) * fx;
        px[k] = static_cast<float>(a * (1 - fy) + b * fy);
      }
    }
  }
}

}  // namespace

void apply_tile(WeatherMap& map, const MapTile& t) {
  int source[4];  // map channel k <- the tile's channel bit k (the first four bits)
  for (int k = 0, i = 0; k < 4; ++k) source[k] = (t.channels >> k) & 1u ? i++ : kResampleKeep;
  resample_tile(map, t, source);
  if (t.layer_channels == 0) return;
  // Layer coverage slot k <- the tile's slot bit k, after its channels' values. A map
  // without layer coverage gets it, 0 (no cloud of those layers) where no tile gave any.
  if (!map.has_layer_coverage()) map.layer_coverage.assign(map.rgba.size(), 0.0f);
  for (int k = 0, i = std::popcount(t.channels); k < 4; ++k)
    source[k] = (t.layer_channels >> k) & 1u ? i++ : kResampleKeep;
  resample_into(map.layer_coverage, map.width, map.height, t, source);
}

void resample_tile(WeatherMap& map, const MapTile& t, const int (&slot)[4]) {
  resample_into(map.rgba, map.width, map.height, t, slot);
}

WeatherTimeline::WeatherTimeline(WeatherMap base) { reset(std::move(base)); }

void WeatherTimeline::reset(WeatherMap base) {
  frames_.clear();
  frames_[-std::numeric_limits<double>::infinity()] = Keyframe{std::move(base), next_version_++};
}

void WeatherTimeline::reset(std::vector<std::pair<double, WeatherMap>> keyframes) {
  if (keyframes.empty() || keyframes.size() > kMaxKeyframes)
    throw std::invalid_argument("weather timeline: " + std::to_string(keyframes.size()) + " keyframes, expected 1 to " +
                                std::to_string(kMaxKeyframes));
  for (const auto& [t, map] : keyframes)
    if (!std::isfinite(t) || map.width != keyframes.front().second.width || map.height != keyframes.front().second.height)
      throw std::invalid_argument("weather timeline: keyframes need finite times and one size");
  frames_.clear();
  for (auto& [t, map] : keyframes) frames_[t] = Keyframe{std::move(map), next_version_++};
}

std::map<double, WeatherTimeline::Keyframe>::const_iterator WeatherTimeline::keyframe_in_use(double t) const {
  // upper_bound(t) is the first keyframe valid after t; the one before it is in use. When
  // t precedes every keyframe (a clock set back past the oldest one kept), the oldest one
  // stands for all earlier times. frames_ is never empty (reset and the constructor add one).
  auto after = frames_.upper_bound(t);
  return after == frames_.begin() ? after : std::prev(after);
}

void WeatherTimeline::apply(const MapTile& tile, double now_utc_s, double transition_s) {
  const double when = tile.valid_at_utc_s > now_utc_s ? tile.valid_at_utc_s : now_utc_s + transition_s;
  auto it = frames_.find(when);
  if (it == frames_.end()) {
    // At the limit, the oldest keyframe goes if it is no longer in use at now; otherwise
    // (every keyframe is current or ahead) the tile merges into the farthest one.
    if (frames_.size() >= kMaxKeyframes && frames_.begin() != keyframe_in_use(now_utc_s)) frames_.erase(frames_.begin());
    if (frames_.size() >= kMaxKeyframes) {
      it = std::prev(frames_.end());
    } else {
      // A new keyframe starts as a copy of the state valid at `when`.
      const Keyframe& before = keyframe_in_use(when)->second;
      it = frames_.emplace(when, Keyframe{before.map, 0}).first;
    }
  }
  apply_tile(it->second.map, tile);
  it->second.version = next_version_++;
  // Later keyframes inherit the change where they do not have their own data: apply
  // the tile to them too, so a forecast for later is not undone by an older keyframe.
  for (auto later = std::next(it); later != frames_.end(); ++later) {
    apply_tile(later->second.map, tile);
    later->second.version = next_version_++;
  }
}

WeatherTimeline::Blend WeatherTimeline::at(double t) const {
  const auto cur = keyframe_in_use(t);
  Blend b;
  b.from = &cur->second.map;
  b.from_version = cur->second.version;
  const auto next = std::next(cur);
  if (next == frames_.end()) {
    b.to = b.from;
    b.to_version = b.from_version;
    return b;
  }
  b.to = &next->second.map;
  b.to_version = next->second.version;
  // Linear in time between the two valid-at times; the base keyframe (valid since
  // forever) fades over the transition before the next one. Before the oldest keyframe
  // (t < cur->first) the weight clamps to 0; a non-finite t gets 0, never NaN.
  const double span = std::isfinite(cur->first) ? next->first - cur->first : kDefaultTransition_s;
  const double w = 1.0 - (next->first - t) / span;
  b.weight = std::isfinite(w) ? static_cast<float>(std::clamp(w, 0.0, 1.0)) : 0.0f;
  return b;
}

}  // namespace cloudsvc::weather
