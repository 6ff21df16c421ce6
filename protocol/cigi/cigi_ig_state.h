// What a CIGI host has told the IG so far (cigi_packets.h): the ownship's pose, the views
// attached to it, the date and time, the atmosphere, and the cloud layers, global and of
// regions. The service draws its frames from this state (docs/CIGI.md, "State"); applying a
// datagram changes it packet by packet, in order, and never partly applies a packet.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "protocol/cigi/cigi_datagram.h"

namespace cloudsvc::cigi {

// A view's frustum: half-angles from its axis (degrees; left and bottom usually negative)
// and clipping planes (m along the view axis; 0 = not given, no plane). Clouds outside the
// planes are not drawn (ViewRequest::near_m, far_m).
struct ViewFrustum {
  float left_deg = -30.0f, right_deg = 30.0f, top_deg = 17.5f, bottom_deg = -17.5f;
  float near_m = 0.0f, far_m = 0.0f;
  bool operator==(const ViewFrustum&) const = default;
};

// A view (channel) attached to the ownship.
struct View {
  std::uint16_t id = 0;
  std::uint8_t group = 0;
  float x_m = 0.0f, y_m = 0.0f, z_m = 0.0f;  // eye offset in the ownship's body axes (x forward, y right, z down), m
  float roll_deg = 0.0f, pitch_deg = 0.0f, yaw_deg = 0.0f;  // rotation from the ownship's attitude
  ViewFrustum frustum;
  std::uint8_t mirror = 0;  // View Definition's mirror mode: 0 none, 1 horizontal, 2 vertical, 3 both
  bool operator==(const View&) const = default;
};

struct OwnshipPose {
  double lat_deg = 0.0, lon_deg = 0.0;  // WGS84
  double alt_m = 0.0;                   // above mean sea level (used as above the ellipsoid: docs/CIGI.md)
  double roll_deg = 0.0, pitch_deg = 0.0, yaw_deg = 0.0;
  bool operator==(const OwnshipPose&) const = default;
};

// Cloud layers 1..3 of a scope (global or a region): the last enabled Weather Control of
// each, or none.
using CloudLayerSet = std::array<std::optional<WeatherControl>, 3>;

struct Region {
  EnvironmentalRegionControl control;
  CloudLayerSet layers;
};

class IgState {
 public:
  // At most this many views; a View Control or Definition of another view id beyond it is
  // refused (the IG renders every view each frame).
  static constexpr std::size_t kMaxViews = 8;
  // At most this many regions (each is resampled onto the weather map).
  static constexpr std::size_t kMaxRegions = 64;

  // The frustum of a view the host has not defined (the IG's configured field of view).
  explicit IgState(ViewFrustum default_frustum = {});

  // Applies a usable datagram's IG Control and packets in order; returns one line for each
  // packet refused at this stage (e.g. a view beyond kMaxViews, a regional layer of a region
  // not defined), in the form of Rejection::reason.
  std::vector<std::string> apply(const HostDatagram& d);

  IgMode mode() const { return mode_; }
  std::uint32_t last_host_frame() const { return last_host_frame_; }
  // The last IG Control's timestamp, s (its ticks of 10 µs), when it said it was valid.
  const std::optional<double>& host_timestamp_s() const { return host_timestamp_s_; }
  std::uint64_t datagrams() const { return datagrams_; }
  const std::optional<OwnshipPose>& ownship() const { return ownship_; }
  // The views by id; view 0 with the default frustum when the host has defined none.
  std::vector<View> views() const;
  // UTC seconds of the last valid Celestial Sphere Control, if any.
  const std::optional<double>& utc_s() const { return utc_s_; }
  // The last Atmosphere Control, as the host sent it (its visibility is drawn as the haze:
  // cigi_visibility in cigi_weather.h; the other fields are kept, not drawn).
  const std::optional<AtmosphereControl>& atmosphere() const { return atmosphere_; }
  // Rises with every change of the Atmosphere Control's visibility (the haze to redraw).
  std::uint64_t atmosphere_generation() const { return atmosphere_generation_; }
  const CloudLayerSet& global_layers() const { return global_layers_; }
  const std::map<std::uint16_t, Region>& regions() const { return regions_; }
  // Rises with every change of the cloud layers or regions (the weather to rebuild), not
  // with a packet that changes nothing (hosts resend their weather every frame); 0 until the
  // host's first Weather Control or region, which raises it even when it only disables a
  // layer (the host's weather, then, has no cloud there).
  std::uint64_t weather_generation() const { return weather_generation_; }

 private:
  std::optional<std::string> apply(const HostPacket& p);

  ViewFrustum default_frustum_;
  IgMode mode_ = IgMode::Standby;
  std::uint32_t last_host_frame_ = 0;
  std::optional<double> host_timestamp_s_;
  std::uint64_t datagrams_ = 0;
  std::optional<OwnshipPose> ownship_;
  std::map<std::uint16_t, View> views_;
  std::optional<double> utc_s_;
  std::optional<AtmosphereControl> atmosphere_;
  std::uint64_t atmosphere_generation_ = 0;
  CloudLayerSet global_layers_;
  std::map<std::uint16_t, Region> regions_;
  std::uint64_t weather_generation_ = 0;
};

}  // namespace cloudsvc::cigi
