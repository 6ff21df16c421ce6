// The frames a CIGI host asks for (`cloudsvc serve --cigi`, docs/CIGI.md), on the render
// thread: the host's datagrams are applied in order to the IG's state (cigi::IgState); each
// IG frame starts with a Start of Frame (carrying the IG Messages waiting: every packet not
// used, every note about the weather) and then renders every view of the ownship from one
// frame state: the weather, sun, LUTs and shadow map are shared, only the view-dependent
// passes run per view (CloudRenderer channels). Each view's image goes to its own ring
// (NAME-view<ID>), its own files (DIR/view<ID>/frame_<IG frame>.png) and, for the first
// view, the window.
//
// Pacing (serve_options.h, CigiPacing):
//   synchronous: one IG frame per usable host datagram (host frame), in order; with no host
//     frame waiting, the last Start of Frame is sent again (same IG frame number) after 1 s,
//     or after 0.1 s when IG Messages wait, so a host that lost a datagram, or that waits for
//     the IG to speak first, goes on.
//   asynchronous: datagrams are applied as they come; an IG frame every 1 / --cigi-rate s
//     from the newest state.
// In Standby the IG frames carry a Start of Frame and render nothing; so do frames before the
// host has sent the ownship's Entity Control.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "protocol/cigi/cigi_ig_messages.h"
#include "protocol/cigi/cigi_ig_state.h"
#include "protocol/cigi/cigi_view_pose.h"
#include "renderer/api/frame_image.h"
#include "service/serve_options.h"

namespace cloudsvc {

class CloudRenderer;
class ViewRings;
class WindowPresenter;

class CigiFrames {
 public:
  using Clock = std::chrono::steady_clock;
  using Send = std::function<void(std::vector<std::uint8_t>)>;  // to the host, via the network thread
  // Host frames a synchronous IG keeps waiting; older ones are applied without a frame of
  // their own (counted, and an IG Message says so).
  static constexpr std::size_t kMaxHostFramesWaiting = 64;
  // The channel of CIGI view ID in the renderer is kChannelBase + ID (channel 0 is the
  // protocol clients' view).
  static constexpr int kChannelBase = 1;

  struct Outputs {
    ViewRings* rings = nullptr;            // --shm; null = none
    WindowPresenter* window = nullptr;     // --window; null = none
    std::mutex* publish_mutex = nullptr;   // held while a sink is written
  };

  // `weather_taken` is called when the host's cloud layers replace the service's weather.
  CigiFrames(const ServeOptions& options, CloudRenderer& renderer, Outputs outputs, Send send,
             std::function<void()> weather_taken);

  // Datagrams from the network thread, in arrival order; `refused` were lost to the
  // mailbox's bound.
  void receive(std::vector<cigi::HostDatagram> datagrams, std::uint64_t refused);
  // How long until step() has something to do (zero: now).
  Clock::duration wait(Clock::time_point now) const;
  // Does what is due at `now`: at most one IG frame, or a Start of Frame sent again. Returns
  // the number of views rendered.
  int step(Clock::time_point now);

  std::uint32_t ig_frame() const { return ig_frame_; }
  // Packets and datagrams of the host not used (lost to the mailbox's bound included).
  std::uint64_t packets_rejected() const { return rejected_; }
  std::uint64_t host_frames_merged() const { return merged_; }
  const cigi::IgState& state() const { return state_; }

 private:
  void apply(const cigi::HostDatagram& d);
  // A packet or datagram not used: counted, then reported.
  void reject(const std::string& line);
  // An IG Message for the host (and, the first 20, a line on stdout).
  void report(const std::string& line);
  // One IG frame: Start of Frame, then every view.
  int frame(Clock::time_point now);
  cigi::StartOfFrame start_of_frame() const;
  void send_start_of_frame(Clock::time_point now);
  // The host's weather, before a frame: its cloud layers (update_cloud_layers), then its
  // Atmosphere Control's visibility (update_visibility).
  void update_weather();
  void update_cloud_layers();
  // A new visibility (cigi::cigi_visibility) goes into the weather drawn: the host's cloud
  // layers', or, before it has sent any, the service's own; a clamped one is reported.
  void update_visibility();
  int render_views(double utc_s);
  void publish(const cigi::View& v, const cigi::ViewPose& pose, const FrameImage& img, double utc_s, bool first_view);
  // The frustum of a view the host has not defined: --fov wide, --size's aspect (square pixels).
  static cigi::ViewFrustum default_frustum(const ServeOptions& o);

  const ServeOptions& options_;
  CloudRenderer& renderer_;
  Outputs outputs_;
  Send send_;
  std::function<void()> weather_taken_;
  cigi::IgState state_;
  cigi::IgMessageOutbox outbox_;
  std::deque<cigi::HostDatagram> waiting_;  // synchronous: usable host frames not yet drawn
  bool host_known_ = false;                 // a datagram came, or --cigi-host names the host
  cigi::ByteOrder host_order_ = cigi::ByteOrder::Big;
  std::uint32_t ig_frame_ = 0;              // of the last Start of Frame sent
  Clock::time_point start_, last_sent_, next_async_frame_;
  std::uint64_t weather_generation_ = 0;    // of the state, drawn
  cigi::CloudLayerSet defining_layers_;     // near the ownship, drawn (cigi::defining_layers)
  std::uint64_t atmosphere_generation_ = 0;  // of the state, drawn
  std::uint64_t rejected_ = 0, reported_ = 0, merged_ = 0;
  bool told_no_ownship_ = false;
  std::set<std::uint16_t> ring_failed_;     // views whose ring could not be made (said once)
  std::set<std::uint16_t> file_failed_;     // views whose file could not be written (said once)
};

}  // namespace cloudsvc
