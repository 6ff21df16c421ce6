// The host -> IG datagrams of `sim_client cigi` (cigi_host_frames.h).
#include "sim_client/cigi_host_frames.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "weather/cloud_water.h"

namespace cloudsvc::sim {

namespace {
constexpr double kDeg = 180.0 / 3.14159265358979323846;
}

std::vector<cigi::ViewDefinition> side_by_side_views(int count, double hfov_deg, double aspect_height_over_width) {
  std::vector<cigi::ViewDefinition> views;
  const double half_v = std::atan(std::tan(0.5 * hfov_deg / kDeg) * aspect_height_over_width) * kDeg;
  for (int i = 0; i < count; ++i) {
    cigi::ViewDefinition d;
    d.view_id = static_cast<std::uint16_t>(i);
    using namespace cigi::definition_enable;
    d.enable = kLeft | kRight | kTop | kBottom;
    d.left_deg = static_cast<float>(-0.5 * hfov_deg);
    d.right_deg = static_cast<float>(0.5 * hfov_deg);
    d.top_deg = static_cast<float>(half_v);
    d.bottom_deg = static_cast<float>(-half_v);
    views.push_back(d);
  }
  return views;
}

cigi::ViewControl side_by_side_control(const cigi::ViewDefinition& d, int count, double hfov_deg) {
  cigi::ViewControl c;
  c.view_id = d.view_id;
  c.entity_id = 0;
  c.enable = cigi::view_enable::kYaw;
  c.yaw_deg = static_cast<float>((d.view_id - 0.5 * (count - 1)) * hfov_deg);
  return c;
}

std::vector<cigi::WeatherControl> global_weather_controls(const weather::Weather& w) {
  if (w.layers.size() > 3)
    throw std::invalid_argument("weather " + w.name + ": " + std::to_string(w.layers.size()) +
                                " cloud layers; CIGI Weather Control carries 3 (layers 1-3)");
  std::vector<cigi::WeatherControl> out;
  for (std::uint8_t id = cigi::kFirstCloudLayerId; id <= cigi::kLastCloudLayerId; ++id) {
    cigi::WeatherControl c;
    c.layer_id = id;
    c.scope = cigi::WeatherScope::Global;
    const std::size_t i = id - cigi::kFirstCloudLayerId;
    if (i >= w.layers.size()) {
      c.enabled = false;
      c.cloud_type = 0;
    } else {
      const weather::CloudLayer& l = w.layers[i];
      c.enabled = true;
      c.cloud_type = static_cast<std::uint8_t>(l.type);
      c.base_elevation_m = static_cast<float>(l.base_m);
      c.thickness_m = static_cast<float>(l.top_m - l.base_m);
      c.coverage_pct = static_cast<float>(100.0 * l.coverage);
      // The layer's water content (aerosol concentration, g/m^3) in its type's droplets, which
      // the IG draws in (docs/CIGI.md, "Weather"): the IG draws the layer's density scale.
      c.aerosol_gpm3 = static_cast<float>(
          l.density_scale *
          weather::water_content_of_n0_droplets_g_m3(weather::cloud_type_traits(l.type).default_droplet_diameter_um));
      // The renderer's wind points where the air goes; CIGI's direction is where it comes from.
      const double speed = std::hypot(l.wind.east_mps, l.wind.north_mps);
      c.wind_horizontal_mps = static_cast<float>(speed);
      double from = speed > 0.0 ? std::atan2(-l.wind.east_mps, -l.wind.north_mps) * kDeg : 0.0;
      if (from < 0.0) from += 360.0;
      c.wind_direction_deg = static_cast<float>(from);
    }
    out.push_back(c);
  }
  return out;
}

cigi::CelestialSphereControl celestial_control(double utc_unix_s) {
  using namespace std::chrono;
  const auto t = sys_seconds(seconds(static_cast<long long>(std::floor(utc_unix_s))));
  const sys_days day = floor<days>(t);
  const year_month_day ymd(day);
  const hh_mm_ss hms(t - day);
  cigi::CelestialSphereControl c;
  c.hour = static_cast<std::uint8_t>(hms.hours().count());
  c.minute = static_cast<std::uint8_t>(hms.minutes().count());
  c.date_valid = true;
  c.date = static_cast<std::uint32_t>(static_cast<unsigned>(ymd.month()) * 1000000u +
                                      static_cast<unsigned>(ymd.day()) * 10000u +
                                      static_cast<unsigned>(static_cast<int>(ymd.year())));
  return c;
}

std::vector<std::uint8_t> host_datagram(const HostFrame& f, cigi::ByteOrder order) {
  cigi::DatagramWriter w(order);
  cigi::IgControl ig;
  ig.mode = cigi::IgMode::Operate;
  ig.host_frame = f.host_frame;
  ig.last_ig_frame = f.last_ig_frame;
  ig.timestamp_valid = true;
  ig.timestamp = static_cast<std::uint32_t>(static_cast<std::uint64_t>(std::llround(f.pose.sim_time_s * cigi::kTimestampTicksPerSecond)));
  w.add(ig);
  if (f.views)
    for (const cigi::ViewDefinition& d : *f.views) {
      w.add(d);
      w.add(side_by_side_control(d, f.view_count, f.view_hfov_deg));
    }
  if (f.weather)
    for (const cigi::WeatherControl& c : global_weather_controls(*f.weather)) w.add(c);
  if (f.pose.utc_unix_s) w.add(celestial_control(*f.pose.utc_unix_s));
  cigi::EntityControl e;
  e.entity_id = 0;
  e.state = 1;
  e.lat_deg = f.pose.lat_deg;
  e.lon_deg = f.pose.lon_deg;
  e.alt_m = f.pose.alt_m;
  e.yaw_deg = static_cast<float>(f.pose.heading_deg);
  e.pitch_deg = static_cast<float>(f.pose.pitch_deg);
  e.roll_deg = static_cast<float>(f.pose.roll_deg);
  w.add(e);
  return w.bytes();
}

}  // namespace cloudsvc::sim
