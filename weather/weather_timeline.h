// Streamed weather-map updates over time. The global map is a set of
// keyframes, each a full WeatherMap valid at a UTC time; the renderer blends the two
// keyframes around the current time, so a new forecast fades in instead of popping.
//
// A tile (a georeferenced patch of some channels, weather/map_tile.h) updates the keyframe at its valid-at
// time; a missing keyframe is created as a copy of the state valid then. A tile valid
// at or before "now" would pop, so it goes into a keyframe at now + transition instead.
// Any time may be asked for, in any order (a simulator may set its clock back or replay
// an older flight): keyframes in the past are kept, so going back shows the weather that
// was valid then; times before the oldest keyframe kept use that one. At most
// kMaxKeyframes are kept: at the limit the oldest keyframe no longer in use at "now" is
// dropped, and when every keyframe is current or ahead the new tile merges into the last.
#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "weather/map_tile.h"
#include "weather/weather_map.h"

namespace cloudsvc::weather {

// Writes the tile's weather-map channels (kWeatherMapTileChannels) and layer-coverage slots
// (MapTile::layer_channels) into `map` at every map texel whose centre lies inside the tile
// (bilinear resampling of the tile; seamless across the antimeridian). A map without layer
// coverage that gets a slot gets all four, 0 outside the tile.
void apply_tile(WeatherMap& map, const MapTile& tile);

// The resampling of apply_tile with the destination chosen per map channel k of rgba:
// source[k] >= 0 writes the tile's value at texel slot source[k] (its index among the
// tile's channels, ascending bit order), kResampleKeep leaves the channel as it is and
// kResampleOne writes 1 (e.g. a weight: "a tile covers this texel").
inline constexpr int kResampleKeep = -1;
inline constexpr int kResampleOne = -2;
void resample_tile(WeatherMap& map, const MapTile& tile, const int (&source)[4]);

class WeatherTimeline {
 public:
  static constexpr std::size_t kMaxKeyframes = 8;
  static constexpr double kDefaultTransition_s = 30.0;

  explicit WeatherTimeline(WeatherMap base = {});

  // Replaces everything with one keyframe (e.g. a new procedural map).
  void reset(WeatherMap base);
  // Replaces everything with keyframes valid at the given UTC times (forecast steps; at
  // least one, at most kMaxKeyframes, all of one size). Throws std::invalid_argument otherwise.
  void reset(std::vector<std::pair<double, WeatherMap>> keyframes);
  // Applies a tile (which must have no problem()) given the current UTC time.
  void apply(const MapTile& tile, double now_utc_s, double transition_s = kDefaultTransition_s);

  struct Blend {
    const WeatherMap* from = nullptr;  // keyframe at or before t
    const WeatherMap* to = nullptr;    // next keyframe (== from when none)
    float weight = 0.0f;               // 0 -> from, 1 -> to
    std::uint64_t from_version = 0, to_version = 0;  // change counters, for GPU uploads
  };
  // The keyframes around t, for any t (finite or not, before, between or after the
  // keyframes); the weight is always finite, in [0, 1].
  Blend at(double t_utc_s) const;

  std::size_t keyframe_count() const { return frames_.size(); }

 private:
  struct Keyframe {
    WeatherMap map;
    std::uint64_t version = 0;
  };
  // The keyframe whose validity holds t: the last one at or before t, else the oldest.
  std::map<double, Keyframe>::const_iterator keyframe_in_use(double t) const;

  std::map<double, Keyframe> frames_;  // by valid-at UTC, never empty; the first entry covers all earlier times
  std::uint64_t next_version_ = 1;
};

}  // namespace cloudsvc::weather
