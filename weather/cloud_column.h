// A forecast's clouds over one point at one time, and the cloud layers the renderer draws
// for them. The rules are in docs/WEATHER.md, "GRIB2 forecasts"; in short:
//   - low band -> stratocumulus, or cumulus where shallow convection (convective cloud
//     whose top is below kDeepConvectionTop_m) makes up at least kCumulusShareOfLowCloud of it,
//     or stratus when its base is within kStratusBaseAboveGround_m of the ground (when the
//     ground's height is known);
//   - convective cloud reaching kDeepConvectionTop_m or higher -> cumulonimbus;
//   - middle band -> altocumulus, or altostratus from cover kSheetCover (broken and
//     overcast middle cloud is a sheet);
//   - high band -> cirrus, or cirrostratus from cover kSheetCover;
//   - a band with cover but no base or top takes its cloud type's default altitudes.
// Layers keep to the renderer's rules (weather::validate): at most four, sorted, apart.
// Where two overlap (a cumulonimbus through a deck), the one covering more of the sky keeps
// its altitudes and the other keeps the larger free part of its range.
#pragma once

#include <array>
#include <limits>
#include <vector>

#include "weather/cloud_layer.h"
#include "weather/grib_cloud_fields.h"

namespace cloudsvc::weather {

// One band at a point: cover fraction [0, 1] and base / top in m above mean sea level
// (metres above the ellipsoid in the renderer: cloud_layer.h). NaN = not given.
struct BandValues {
  double cover = std::numeric_limits<double>::quiet_NaN();
  double base_m = std::numeric_limits<double>::quiet_NaN();
  double top_m = std::numeric_limits<double>::quiet_NaN();
};

// Cloud cover on one level of a profile at a point: the level's altitude (m above mean sea
// level) and its cover [0, 1].
struct ProfileSample {
  double altitude_m = 0.0;
  double cover = 0.0;
};

// The bands of CloudBand but Profile, indexed by the enum's value.
inline constexpr int kColumnBands = 6;
struct CloudColumn {
  std::array<BandValues, kColumnBands> bands;
  double ground_m = std::numeric_limits<double>::quiet_NaN();  // the ground's height there, when known
  BandValues& operator[](CloudBand b) { return bands[static_cast<int>(b)]; }
  const BandValues& operator[](CloudBand b) const { return bands[static_cast<int>(b)]; }
};

// Linear blend of two columns (weight w of b), field by field; a field given in only one of
// them holds (NaN = not given). The ground's height is a's, else b's. Forecast steps and
// reports in time blend this way.
CloudColumn blend_columns(const CloudColumn& a, const CloudColumn& b, double w);

// A weighted average of columns (regions, aerodromes): each band's cover over the columns
// that give it, its base and top weighted by cover as well (so they come from where the
// cloud is; covers under kLeastLayerCover count for cover only), the ground's height over
// the columns that know it. Bands no column gives stay NaN.
class ColumnAverage {
 public:
  void add(const CloudColumn& c, double weight);
  CloudColumn result() const;

 private:
  struct Sum {
    double w = 0, cover = 0, wc_base = 0, base = 0, wc_top = 0, top = 0;
  };
  Sum sums_[kColumnBands];
  double ground_w_ = 0.0, ground_ = 0.0;
};

// Heights separating the low, middle and high bands of a cloud-cover profile: the
// standard-atmosphere altitudes of sigma = p / p_surface = 0.8 and 0.45 with p_surface =
// 101325 Pa, the bands of ECMWF's low, medium and high cloud cover (IFS Documentation
// Cy47r3, Part IV, section 7.7), about 1.95 km and 6.3 km.
double low_middle_boundary_m();
double middle_high_boundary_m();

// Fills the low, middle and high bands that have no cover from a cloud-cover profile:
// cover = the largest cover of the band's levels (maximum overlap); base and top = the
// lowest and highest level with cover >= kProfileCloudyCover, widened by half the distance
// to the next level below and above. Samples may come in any order.
inline constexpr double kProfileCloudyCover = 0.05;
void fill_bands_from_profile(CloudColumn& column, std::vector<ProfileSample> profile);

// Convective cloud whose top reaches this height (m above sea level) is cumulonimbus:
// towering cumulus and cumulonimbus reach 6 km and more (WMO International Cloud Atlas,
// 2017: cumulonimbus tops typically 6-12 km at mid-latitudes).
inline constexpr double kDeepConvectionTop_m = 6000.0;
// Share of the low cloud that convective cloud must make up for the low layer to be cumulus.
inline constexpr double kCumulusShareOfLowCloud = 0.5;
// Middle and high cloud from this cover on is a sheet (altostratus, cirrostratus).
inline constexpr double kSheetCover = 0.5;
// Low cloud without convection whose base is this close to the ground is stratus: stratus
// bases lie between the surface and about 600 m, mostly under 300 m (WMO International Cloud
// Atlas, 2017, "Stratus"); stratocumulus bases are higher.
inline constexpr double kStratusBaseAboveGround_m = 300.0;
// A band below this cover is clear (no layer).
inline constexpr double kLeastLayerCover = 0.01;
// Thinnest layer made from a band: a band whose top is less than this above its base (one
// model level, or equal pressures) is widened upwards to it.
inline constexpr double kLeastBandThickness_m = 300.0;

// The renderer's layer slots of forecast weather: the low cloud (stratus, stratocumulus or
// cumulus), the middle and high cloud and deep convection (cumulonimbus). A layer made from
// slot k reads its local coverage from channel k of the weather map's layer coverage
// (CloudLayer::coverage_channel, weather_map.h).
inline constexpr int kLayerSlots = 4;
inline constexpr int kLowSlot = 0, kMiddleSlot = 1, kHighSlot = 2, kDeepConvectionSlot = 3;

// A slot's cloud type and band at a column (the band the slot's layer is made from).
struct SlotBand {
  CloudType type = CloudType::Stratocumulus;
  BandValues band;
};
// The column's slots by the rules above (cover NaN or 0 where a slot has no cloud).
std::array<SlotBand, kLayerSlots> slot_bands(const CloudColumn& column);

// The layers of the slots, each with its slot as coverage channel, sorted by base and placed
// apart; weather::validate accepts them.
std::vector<CloudLayer> layers_from_slots(const std::array<SlotBand, kLayerSlots>& slots);

// The renderer's layers for a column: layers_from_slots(slot_bands(column)).
std::vector<CloudLayer> layers_from_column(const CloudColumn& column);

// The cover of each slot at a column (0 where it has none): the layer-coverage channels of
// the weather map at that point.
std::array<float, kLayerSlots> slot_covers(const CloudColumn& column);

}  // namespace cloudsvc::weather
