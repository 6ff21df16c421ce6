// Which GRIB2 fields describe clouds, and what each one means to the renderer.
//
// A field is recognised by its GRIB2 identity: discipline, parameter category and number
// (WMO Manual on Codes, GRIB2 Code Table 4.2) and the type of its first fixed surface
// (Code Table 4.5), with the units the WMO table gives them; fields from a centre's local
// tables are recognised by the ecCodes paramId that names them (ECMWF's tcc/lcc/mcc/hcc),
// with the units ecCodes gives them (% or a fraction 0-1). The table is in
// docs/WEATHER.md, "GRIB2 forecasts".
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace cloudsvc::weather {

// The cloud bands of a forecast. Low, Middle, High, Convective and BoundaryLayer are the
// layers numerical models diagnose (GRIB2 surface types 211-244); Total is the whole
// column (or cloud base / top of the lowest / highest cloud); Profile is cloud cover on
// pressure, height or model levels.
enum class CloudBand { Total, Low, Middle, High, Convective, BoundaryLayer, Profile };
std::string_view cloud_band_name(CloudBand b);

// What a field gives: cover (fraction of the sky), the base or top of the band's cloud, or
// the height of the ground (to turn heights above ground into heights above sea level).
enum class CloudQuantity { Cover, Base, Top, Orography };

// How a base, top or orography field measures height.
enum class HeightMeasure {
  None,                 // cover fields
  Pressure_Pa,          // -> altitude of that pressure in the ICAO standard atmosphere
  Geopotential_m2ps2,   // -> geopotential height Phi / g0 -> geometric height
  GeopotentialHeight_m, // gpm -> geometric height
  AboveSea_m,           // geometric height above mean sea level
  AboveGround_m,        // geometric height above the ground (+ orography when present)
};

// The kind of vertical level of a Profile field.
enum class ProfileLevel { None, Pressure_Pa, AboveSea_m, AboveGround_m, Hybrid };

struct CloudFieldRole {
  CloudBand band = CloudBand::Total;
  CloudQuantity quantity = CloudQuantity::Cover;
  HeightMeasure measure = HeightMeasure::None;
  ProfileLevel level = ProfileLevel::None;  // Profile fields only
  double cover_scale = 1.0;                 // cover fields: multiplier to a fraction 0-1
};

// The keys of a GRIB2 message that identify it (ecCodes key names in comments).
struct GribIdentity {
  long discipline = 0;      // discipline
  long category = 0;        // parameterCategory
  long number = 0;          // parameterNumber
  long level_type = 0;      // typeOfFirstFixedSurface
  long param_id = 0;        // paramId (the centre's table applied)
  std::string short_name;   // shortName, for messages
  std::string units;        // units, e.g. "%" or "(0 - 1)"
};

// The field's role, or nullopt when it does not describe clouds (it is then ignored).
// A local cloud-cover field whose units are neither a percentage nor a fraction is a cloud
// field with a problem: `problem` receives it ("cloud cover in units 'okta', neither % nor a
// fraction 0-1").
std::optional<CloudFieldRole> classify_cloud_field(const GribIdentity& id, std::string* problem);

}  // namespace cloudsvc::weather
