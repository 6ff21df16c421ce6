// GRIB2 cloud fields through ecCodes (grib_reader.h).
#include "weather/grib_reader.h"

#include <eccodes.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string_view>

#include "geodesy/utc_time.h"
#include "weather/file_extension.h"
#include "weather/standard_atmosphere.h"
#include "weather/weather_json.h"

namespace cloudsvc::weather {

namespace {

// ecCodes reports its errors through a logging procedure (by default to stderr). The
// reader keeps the last one to name the cause in its own one-line message instead.
thread_local std::string g_last_eccodes_message;
void keep_eccodes_message(const codes_context*, int level, const char* message) {
  if (level == CODES_LOG_ERROR || level == CODES_LOG_FATAL) g_last_eccodes_message = message ? message : "";
}
// ecCodes stops the process (abort) when a decoder's consistency check fails, as it does on
// some damaged data sections (e.g. complex packing whose group sizes exceed the values).
// Bad input must not stop the service: the check's procedure throws instead, and the reader
// turns that into a one-line error about the message. The exception unwinds through
// ecCodes' C frames (built with unwind tables, as Debian's x86_64 and arm64 builds are); what
// ecCodes allocated for that message is leaked, once per damaged message.
struct EccodesCheckFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};
void throw_eccodes_check(const char* message) { throw EccodesCheckFailed(message ? message : "?"); }

}  // namespace
}  // namespace cloudsvc::weather

// In the sanitizer build, LeakSanitizer is told about that one known leak (what ecCodes
// allocated for a damaged message when its check threw), and no other: only allocations
// made inside libeccodes are exempt.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CLOUDSVC_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(CLOUDSVC_ASAN)
extern "C" const char* __lsan_default_suppressions() { return "leak:libeccodes.so\n"; }
#endif

namespace cloudsvc::weather {
namespace {

void route_eccodes_logging() {
  static const bool routed = [] {
    codes_context_set_logging_proc(codes_context_get_default(), keep_eccodes_message);
    codes_set_codes_assertion_failed_proc(throw_eccodes_check);
    return true;
  }();
  (void)routed;
}

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw WeatherFileError(path + ": " + problem);
}

struct HandleDeleter {
  void operator()(codes_handle* h) const { codes_handle_delete(h); }
};
using Handle = std::unique_ptr<codes_handle, HandleDeleter>;
struct FileCloser {
  void operator()(FILE* f) const { std::fclose(f); }
};

long get_long(codes_handle* h, const char* key, long fallback = 0) {
  long v = fallback;
  return codes_get_long(h, key, &v) == 0 ? v : fallback;
}
std::string get_string(codes_handle* h, const char* key) {
  char buf[256] = {};
  std::size_t len = sizeof buf;
  return codes_get_string(h, key, buf, &len) == 0 ? std::string(buf) : std::string();
}
// A double array key; empty with *error set on failure.
std::vector<double> get_doubles(codes_handle* h, const char* key, int* error) {
  std::size_t n = 0;
  *error = codes_get_size(h, key, &n);
  if (*error != 0) return {};
  std::vector<double> v(n);
  *error = codes_get_double_array(h, key, v.data(), &n);
  v.resize(n);
  return v;
}

std::string eccodes_reason(int error) {
  std::string reason = codes_get_error_message(error);
  if (!g_last_eccodes_message.empty()) reason += " (" + g_last_eccodes_message + ")";
  g_last_eccodes_message.clear();
  return reason;
}

// Validity time from validityDate (YYYYMMDD) and validityTime (HHMM), UTC seconds.
double validity_time(codes_handle* h, const std::string& path, const std::string& label) {
  const long date = get_long(h, "validityDate", -1);
  const long time = get_long(h, "validityTime", -1);
  char iso[96];
  std::snprintf(iso, sizeof iso, "%04ld-%02ld-%02ldT%02ld:%02ld:00Z", date / 10000, date / 100 % 100, date % 100,
                time / 100, time % 100);
  const std::optional<double> t = geo::parse_utc_iso8601(iso);
  if (date < 0 || time < 0 || !t) fail(path, label + ": no valid validity time (validityDate " + std::to_string(date) + ", validityTime " + std::to_string(time) + ")");
  return *t;
}

// Value of the message's first fixed surface in its own unit (Pa, m, level number).
double first_surface_value(codes_handle* h) {
  const long scaled = get_long(h, "scaledValueOfFirstFixedSurface", 0);
  const long factor = get_long(h, "scaleFactorOfFirstFixedSurface", 0);
  return static_cast<double>(scaled) * std::pow(10.0, -static_cast<double>(factor));
}

// Converts a field's values in place to the units of GribCloudMessage.
void convert_values(const CloudFieldRole& role, std::vector<double>& v) {
  for (double& x : v) {
    if (std::isnan(x)) continue;
    switch (role.quantity == CloudQuantity::Cover ? HeightMeasure::None : role.measure) {
      case HeightMeasure::None: x = std::clamp(x * role.cover_scale, 0.0, 1.0); break;
      case HeightMeasure::Pressure_Pa: x = standard_pressure_altitude_m(x); break;
      case HeightMeasure::Geopotential_m2ps2: x = geometric_from_geopotential_m(x / kStandardGravity_mps2); break;
      case HeightMeasure::GeopotentialHeight_m: x = geometric_from_geopotential_m(x); break;
      case HeightMeasure::AboveSea_m:
      case HeightMeasure::AboveGround_m: break;
    }
    if (!std::isfinite(x)) x = std::nan("");
  }
}

}  // namespace

bool is_grib_path(const std::string& path) {
  const std::string ext = lowercase_extension(path);
  return ext == "grib2" || ext == "grb2" || ext == "grib" || ext == "grb";
}

namespace {

// Reads the file's messages into result (counting them as it goes).
void read_messages(const std::string& path, FILE* file, GribReadResult& result) {
  // Latitudes and longitudes of the last grid, reused by messages on the same grid.
  std::string grid_md5;
  std::vector<double> lats, lons;
  for (;;) {
    const long offset = std::ftell(file);
    int error = 0;
    g_last_eccodes_message.clear();
    Handle h(codes_handle_new_from_file(nullptr, file, PRODUCT_GRIB, &error));
    if (!h) {
      if (error == 0 || error == GRIB_END_OF_FILE) break;
      fail(path, "truncated or damaged GRIB message " + std::to_string(result.messages + 1) + " after byte " +
                     std::to_string(offset) + ": " + eccodes_reason(error));
    }
    ++result.messages;
    codes_handle* m = h.get();
    const std::string short_name = get_string(m, "shortName");
    const std::string label = "message " + std::to_string(result.messages) + " (" + short_name + ", " +
                              get_string(m, "typeOfLevel") + ")";
    if (get_long(m, "edition") != 2)
      fail(path, label + ": GRIB edition " + std::to_string(get_long(m, "edition")) +
                     " is not supported, only GRIB2 (convert with: grib_set -s edition=2 IN OUT)");

    GribIdentity id;
    id.discipline = get_long(m, "discipline", -1);
    id.category = get_long(m, "parameterCategory", -1);
    id.number = get_long(m, "parameterNumber", -1);
    id.level_type = get_long(m, "typeOfFirstFixedSurface", -1);
    id.param_id = get_long(m, "paramId", 0);
    id.short_name = short_name;
    id.units = get_string(m, "units");
    std::string problem;
    const std::optional<CloudFieldRole> role = classify_cloud_field(id, &problem);
    if (!role) {
      result.ignored.push_back(short_name);
      continue;
    }
    if (!problem.empty()) fail(path, label + ": " + problem);

    GribCloudMessage out;
    out.role = *role;
    out.label = label;
    out.valid_utc_s = validity_time(m, path, label);
    out.above_ground = role->quantity != CloudQuantity::Cover && role->measure == HeightMeasure::AboveGround_m;
    if (role->band == CloudBand::Profile) {
      out.level_value = role->level == ProfileLevel::Hybrid ? static_cast<double>(get_long(m, "level")) : first_surface_value(m);
      if (role->level == ProfileLevel::Hybrid) {
        out.pv = get_doubles(m, "pv", &error);
        if (error != 0 || out.pv.size() < 2) fail(path, label + ": a model level without vertical coordinate parameters (pv)");
      }
    }

    // Values, with the bitmap's missing points as NaN: ecCodes writes missingValue there,
    // set first to a value no field can hold.
    constexpr double kMissing = 1.0e35;
    const bool bitmap = get_long(m, "bitmapPresent") != 0;
    if (bitmap) codes_set_double(m, "missingValue", kMissing);
    std::vector<double> values;
    try {
      values = get_doubles(m, "values", &error);
    } catch (const EccodesCheckFailed& e) {
      fail(path, label + ": cannot decode values packed as '" + get_string(m, "packingType") + "': the data section is damaged (" +
                     e.what() + ")");
    }
    if (error != 0)
      fail(path, label + ": cannot decode values packed as '" + get_string(m, "packingType") + "': " + eccodes_reason(error));
    if (bitmap)
      for (double& v : values)
        if (v == kMissing) v = std::nan("");

    const std::string md5 = get_string(m, "md5GridSection");
    if (md5.empty() || md5 != grid_md5) {
      lats = get_doubles(m, "latitudes", &error);
      if (error == 0) lons = get_doubles(m, "longitudes", &error);
      if (error != 0)
        fail(path, label + ": grid '" + get_string(m, "gridType") + "' cannot be geolocated: " + eccodes_reason(error));
      grid_md5 = md5;
    }
    if (lats.size() != values.size() || lons.size() != values.size())
      fail(path, label + ": " + std::to_string(values.size()) + " values on a grid of " + std::to_string(lats.size()) + " points");
    convert_values(out.role, values);
    out.field = GridField::from_points(lats, lons, values);
    result.clouds.push_back(std::move(out));
  }
}

}  // namespace

GribReadResult read_grib_cloud_fields(const std::string& path) {
  route_eccodes_logging();
  std::unique_ptr<FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) fail(path, std::string("cannot open: ") + std::strerror(errno));

  GribReadResult result;
  try {
    read_messages(path, file.get(), result);
  } catch (const EccodesCheckFailed& e) {
    fail(path, "damaged GRIB message " + std::to_string(result.messages) + ": ecCodes cannot decode it (" + e.what() + ")");
  }
  if (result.messages == 0) fail(path, "not a GRIB file (no GRIB message found)");
  if (result.clouds.empty()) {
    std::string names;
    for (std::size_t i = 0; i < result.ignored.size() && i < 8; ++i) names += (i ? ", " : "") + result.ignored[i];
    if (result.ignored.size() > 8) names += ", ...";
    fail(path, "no cloud fields among its " + std::to_string(result.messages) + " GRIB messages (" + names +
                   "); expected cloud cover (e.g. tcc, lcc, mcc, hcc) with optional bases and tops");
  }
  return result;
}

}  // namespace cloudsvc::weather
