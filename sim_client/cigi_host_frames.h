// What `sim_client cigi` sends an image generator (docs/SIM_CLIENT.md, "cigi"): the host ->
// IG datagram of each host frame, made from a pose of a flight log or sweep. Every datagram
// is whole on its own (IG Control, the ownship's Entity Control, Celestial Sphere Control
// with the pose's date and time); the first also defines the views, and the weather goes with
// the first frame and whenever it changes.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "protocol/cigi/cigi_datagram.h"
#include "protocol/messages.h"
#include "weather/cloud_layer.h"

namespace cloudsvc::sim {

// Views side by side around the nose: `count` views, each `hfov_deg` wide, their axes
// hfov_deg apart in yaw, the middle one (or the pair around it) on the nose; vertical
// half-angles from the image aspect (square pixels). View ids 0..count-1.
std::vector<cigi::ViewDefinition> side_by_side_views(int count, double hfov_deg, double aspect_height_over_width);
// The View Control that turns view `d` to its place in side_by_side_views.
cigi::ViewControl side_by_side_control(const cigi::ViewDefinition& d, int count, double hfov_deg);

// The global Weather Control packets of a renderer weather: layers 1..3 from its lowest three
// layers (type, base, thickness, coverage, wind), the rest disabled. More than three layers:
// the ones above the third are left out (std::invalid_argument names them).
std::vector<cigi::WeatherControl> global_weather_controls(const weather::Weather& w);

// Celestial Sphere Control for a UTC time (s since the epoch): date and time to the minute.
cigi::CelestialSphereControl celestial_control(double utc_unix_s);

struct HostFrame {
  std::uint32_t host_frame = 0;          // 1, 2, ...
  std::uint32_t last_ig_frame = 0;       // of the last Start of Frame received
  protocol::Pose pose;                   // utc_unix_s set
  const std::vector<cigi::ViewDefinition>* views = nullptr;  // with their controls: first frame
  int view_count = 0;
  double view_hfov_deg = 60.0;
  const weather::Weather* weather = nullptr;  // with the first frame and when it changes
};

// The datagram of one host frame, in `order`.
std::vector<std::uint8_t> host_datagram(const HostFrame& f, cigi::ByteOrder order);

}  // namespace cloudsvc::sim
