// GRIB2 cloud field identities (grib_cloud_fields.h). Sources: WMO Manual on Codes,
// Vol. I.2, GRIB2 Code Tables 4.2-0-3 (mass), 4.2-0-6 (cloud) and 4.5 (fixed surfaces);
// the ECMWF parameter database for the local paramIds.
#include "weather/grib_cloud_fields.h"

namespace cloudsvc::weather {

namespace {

// GRIB2 Code Table 4.5 surface types used here.
constexpr long kGroundSurface = 1, kCloudBaseLevel = 2, kCloudTopLevel = 3, kMeanSeaLevel = 101;
constexpr long kIsobaric = 100, kAltitudeAboveSea = 102, kHeightAboveGround = 103, kHybrid = 105;
constexpr long kEntireAtmosphere = 10, kEntireAtmosphereAsLayer = 200, kNominalTop = 8;
constexpr long kBoundaryLayerCloudLayer = 211;
constexpr long kLowCloudBottom = 212, kLowCloudTop = 213, kLowCloudLayer = 214;
constexpr long kMiddleCloudBottom = 222, kMiddleCloudTop = 223, kMiddleCloudLayer = 224;
constexpr long kHighCloudBottom = 232, kHighCloudTop = 233, kHighCloudLayer = 234;
constexpr long kConvectiveCloudBottom = 242, kConvectiveCloudTop = 243, kConvectiveCloudLayer = 244;

std::optional<CloudBand> band_of_cloud_layer(long level_type) {
  switch (level_type) {
    case kBoundaryLayerCloudLayer: return CloudBand::BoundaryLayer;
    case kLowCloudLayer: return CloudBand::Low;
    case kMiddleCloudLayer: return CloudBand::Middle;
    case kHighCloudLayer: return CloudBand::High;
    case kConvectiveCloudLayer: return CloudBand::Convective;
    case kGroundSurface:
    case kEntireAtmosphere:
    case kEntireAtmosphereAsLayer:
    case kNominalTop: return CloudBand::Total;
    default: return std::nullopt;
  }
}

std::optional<ProfileLevel> profile_level(long level_type) {
  switch (level_type) {
    case kIsobaric: return ProfileLevel::Pressure_Pa;
    case kAltitudeAboveSea: return ProfileLevel::AboveSea_m;
    case kHeightAboveGround: return ProfileLevel::AboveGround_m;
    case kHybrid: return ProfileLevel::Hybrid;
    default: return std::nullopt;
  }
}

// The band and whether the surface is the band's base (true) or top (false).
std::optional<std::pair<CloudBand, bool>> band_of_boundary(long level_type) {
  switch (level_type) {
    case kCloudBaseLevel: return std::pair{CloudBand::Total, true};
    case kCloudTopLevel: return std::pair{CloudBand::Total, false};
    case kLowCloudBottom: return std::pair{CloudBand::Low, true};
    case kLowCloudTop: return std::pair{CloudBand::Low, false};
    case kMiddleCloudBottom: return std::pair{CloudBand::Middle, true};
    case kMiddleCloudTop: return std::pair{CloudBand::Middle, false};
    case kHighCloudBottom: return std::pair{CloudBand::High, true};
    case kHighCloudTop: return std::pair{CloudBand::High, false};
    case kConvectiveCloudBottom: return std::pair{CloudBand::Convective, true};
    case kConvectiveCloudTop: return std::pair{CloudBand::Convective, false};
    default: return std::nullopt;
  }
}

constexpr double kPercent = 0.01;

// Multiplier from the field's units to a fraction, or nullopt.
std::optional<double> cover_scale(std::string_view units) {
  if (units == "%" || units == "percent") return 0.01;
  for (std::string_view fraction : {"(0 - 1)", "0-1", "(0-1)", "Proportion", "proportion", "Fraction", "fraction", "1", "Numeric"})
    if (units == fraction) return 1.0;
  return std::nullopt;
}

// A cover field of a WMO parameter: its units are the table's (% or proportion).
CloudFieldRole wmo_cover(CloudBand band, double scale) {
  CloudFieldRole role{band, CloudQuantity::Cover};
  role.cover_scale = scale;
  return role;
}

// A cover field of a centre's local table: its units as ecCodes names them.
std::optional<CloudFieldRole> local_cover(CloudBand band, const GribIdentity& id, std::string* problem) {
  const std::optional<double> scale = cover_scale(id.units);
  if (!scale && problem) *problem = "cloud cover in units '" + id.units + "', neither % nor a fraction 0-1";
  return wmo_cover(band, scale.value_or(1.0));
}

}  // namespace

std::string_view cloud_band_name(CloudBand b) {
  switch (b) {
    case CloudBand::Total: return "total";
    case CloudBand::Low: return "low";
    case CloudBand::Middle: return "middle";
    case CloudBand::High: return "high";
    case CloudBand::Convective: return "convective";
    case CloudBand::BoundaryLayer: return "boundary-layer";
    case CloudBand::Profile: return "profile";
  }
  return "?";
}

std::optional<CloudFieldRole> classify_cloud_field(const GribIdentity& id, std::string* problem) {
  // ECMWF local parameters (0-1 fractions): tcc 164, lcc 186, mcc 187, hcc 188; cloud base
  // height cbh 228023 (m above the surface).
  switch (id.param_id) {
    case 164: return local_cover(CloudBand::Total, id, problem);
    case 186: return local_cover(CloudBand::Low, id, problem);
    case 187: return local_cover(CloudBand::Middle, id, problem);
    case 188: return local_cover(CloudBand::High, id, problem);
    case 228023: return CloudFieldRole{CloudBand::Total, CloudQuantity::Base, HeightMeasure::AboveGround_m};
    default: break;
  }
  if (id.discipline != 0) return std::nullopt;

  if (id.category == 6) {  // Table 4.2-0-6, cloud
    switch (id.number) {
      case 1:    // total cloud cover, %
      case 7:    // cloud amount, %
      case 22:   // cloud cover, %
      case 32: { // fraction of cloud cover, proportion
        const double scale = id.number == 32 ? 1.0 : kPercent;
        if (std::optional<ProfileLevel> level = profile_level(id.level_type)) {
          CloudFieldRole role = wmo_cover(CloudBand::Profile, scale);
          role.level = *level;
          return role;
        }
        if (std::optional<CloudBand> band = band_of_cloud_layer(id.level_type)) return wmo_cover(*band, scale);
        return std::nullopt;
      }
      case 2: return wmo_cover(CloudBand::Convective, kPercent);  // convective cloud cover, %
      case 3: return wmo_cover(CloudBand::Low, kPercent);         // low cloud cover, %
      case 4: return wmo_cover(CloudBand::Middle, kPercent);      // medium cloud cover, %
      case 5: return wmo_cover(CloudBand::High, kPercent);        // high cloud cover, %
      case 11:   // cloud base, m
      case 12: { // cloud top, m
        const HeightMeasure m = id.level_type == kMeanSeaLevel ? HeightMeasure::AboveSea_m : HeightMeasure::AboveGround_m;
        return CloudFieldRole{CloudBand::Total, id.number == 11 ? CloudQuantity::Base : CloudQuantity::Top, m};
      }
      case 26:   // height of convective cloud base, m
      case 27:   // height of convective cloud top, m
        return CloudFieldRole{CloudBand::Convective, id.number == 26 ? CloudQuantity::Base : CloudQuantity::Top,
                              HeightMeasure::AboveGround_m};
      default: return std::nullopt;
    }
  }
  if (id.category == 3) {  // Table 4.2-0-3, mass: pressure, geopotential, heights
    HeightMeasure measure = HeightMeasure::None;
    switch (id.number) {
      case 0: measure = HeightMeasure::Pressure_Pa; break;
      case 4: measure = HeightMeasure::Geopotential_m2ps2; break;
      case 5: measure = HeightMeasure::GeopotentialHeight_m; break;
      case 6: measure = HeightMeasure::AboveSea_m; break;  // geometric height
      default: return std::nullopt;
    }
    if (std::optional<std::pair<CloudBand, bool>> b = band_of_boundary(id.level_type))
      return CloudFieldRole{b->first, b->second ? CloudQuantity::Base : CloudQuantity::Top, measure};
    // The ground's height: surface geopotential or orography.
    if (id.level_type == kGroundSurface && measure != HeightMeasure::Pressure_Pa)
      return CloudFieldRole{CloudBand::Total, CloudQuantity::Orography, measure};
    return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace cloudsvc::weather
