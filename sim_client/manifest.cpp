// manifest.csv rows (manifest.h).
#include "sim_client/manifest.h"

#include <cmath>
#include <cstdio>

#include "geodesy/utc_time.h"
#include "sim_client/csv_fields.h"

namespace cloudsvc::sim {

namespace {

std::string num(double v, const char* format = "%.10g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// "2026-06-21T12:00:00.250Z": whole seconds from geodesy, milliseconds appended.
std::string utc_text(double t) {
  const double whole = std::floor(t);
  long ms = std::lround((t - whole) * 1000.0);
  double base = whole;
  if (ms == 1000) {
    ms = 0;
    base += 1.0;
  }
  std::string s = geo::format_utc_iso8601(base);  // "...:SSZ"
  char frac[8];
  std::snprintf(frac, sizeof frac, ".%03ld", ms);
  return s.substr(0, s.size() - 1) + frac + "Z";
}

}  // namespace

std::string manifest_header() {
  return "frame,lat,lon,alt,heading,pitch,roll,utc,weather,render_ms,latency_ms,mean_radiance,cloud_fraction,"
         "nonfinite,file";
}

std::string manifest_line(const ManifestRow& r) {
  std::string s = std::to_string(r.frame);
  auto field = [&s](const std::string& text) {
    s += ',';
    s += text;
  };
  for (double v : {r.lat_deg, r.lon_deg, r.alt_m, r.heading_deg, r.pitch_deg, r.roll_deg}) field(num(v));
  field(utc_text(r.utc_unix_s));
  field(csv_quote(r.weather));
  field(num(r.render_ms, "%.3f"));
  field(num(r.latency_ms, "%.3f"));
  field(num(r.stats.mean_radiance, "%.6g"));
  field(num(r.stats.cloud_fraction, "%.6f"));
  field(std::to_string(r.stats.nonfinite));
  field(csv_quote(r.file));
  return s;
}

}  // namespace cloudsvc::sim
