// The CIGI host's frames on the render thread (cigi_frames.h).
#include "service/cigi_frames.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "protocol/cigi/cigi_view_pose.h"
#include "protocol/cigi/cigi_weather.h"
#include "renderer/api/view_request.h"
#include "renderer/cloud_renderer.h"
#include "renderer/quality_presets.h"
#include "service/frame_mailbox.h"
#include "service/frame_mirror.h"
#include "service/frame_sinks.h"
#include "service/view_rings.h"
#include "service/window_presenter.h"

namespace cloudsvc {

namespace {

using namespace std::chrono_literals;

// Synchronous: how long without a host frame before the last Start of Frame goes again.
constexpr auto kResendAfter = std::chrono::duration_cast<CigiFrames::Clock::duration>(1s);
// ... and how soon when IG Messages wait (at most 10 such datagrams a second).
constexpr auto kMessagesAfter = std::chrono::duration_cast<CigiFrames::Clock::duration>(100ms);
// Problems also printed on stdout, for the operator: the first this many.
constexpr std::uint64_t kReportsPrinted = 20;

}  // namespace

CigiFrames::CigiFrames(const ServeOptions& options, CloudRenderer& renderer, Outputs outputs, Send send,
                       std::function<void()> weather_taken)
    : options_(options), renderer_(renderer), outputs_(outputs), send_(std::move(send)),
      weather_taken_(std::move(weather_taken)),
      state_(default_frustum(options)),
      host_known_(options.cigi && options.cigi->host), start_(Clock::now()), last_sent_(start_),
      next_async_frame_(start_) {}

cigi::ViewFrustum CigiFrames::default_frustum(const ServeOptions& o) {
  // The symmetric view of --fov and --size the renderer draws without a frustum.
  ViewRequest r;
  r.fov_deg = o.fov_deg;
  r.width = o.width;
  r.height = o.height;
  const ImageWindow w = image_window(r);
  constexpr double kDeg = 180.0 / 3.14159265358979323846;
  const auto half_x = static_cast<float>(std::atan(w.half_x) * kDeg), half_y = static_cast<float>(std::atan(w.half_y) * kDeg);
  return cigi::ViewFrustum{-half_x, half_x, half_y, -half_y};
}

void CigiFrames::reject(const std::string& line) {
  ++rejected_;
  report(line);
}

void CigiFrames::report(const std::string& line) {
  ++reported_;
  if (reported_ <= kReportsPrinted) {
    std::printf("cloudsvc serve: CIGI: %s%s\n", line.c_str(),
                reported_ == kReportsPrinted ? " (further ones go to the host only)" : "");
    std::fflush(stdout);
  }
  outbox_.add(line);
}

void CigiFrames::apply(const cigi::HostDatagram& d) {
  for (const std::string& line : state_.apply(d)) reject(line);
}

void CigiFrames::receive(std::vector<cigi::HostDatagram> datagrams, std::uint64_t refused) {
  if (refused > 0)
    reject(std::to_string(refused) + " datagrams lost: more than " + std::to_string(FrameMailbox::kMaxCigiDatagrams) +
           " waited for the IG");
  const bool synchronous = options_.cigi->pacing == CigiPacing::Synchronous;
  for (cigi::HostDatagram& d : datagrams) {
    host_known_ = true;
    for (const cigi::Rejection& r : d.rejections) reject(r.reason);
    if (!d.usable) continue;
    host_order_ = d.order;
    if (!synchronous) {
      apply(d);
      continue;
    }
    waiting_.push_back(std::move(d));
    if (waiting_.size() > kMaxHostFramesWaiting) {  // applied, not drawn: the state stays whole
      apply(waiting_.front());
      waiting_.pop_front();
      ++merged_;
      report("host frame " + std::to_string(state_.last_host_frame()) +
             " applied without a frame of its own: more than " + std::to_string(kMaxHostFramesWaiting) +
             " host frames waited (synchronous mode: send the next after its Start of Frame)");
    }
  }
}

CigiFrames::Clock::duration CigiFrames::wait(Clock::time_point now) const {
  constexpr Clock::duration kIdle = std::chrono::duration_cast<Clock::duration>(1h);
  if (!host_known_) return kIdle;
  Clock::time_point due;
  if (options_.cigi->pacing == CigiPacing::Asynchronous) due = next_async_frame_;
  else if (!waiting_.empty()) due = now;
  else due = last_sent_ + (outbox_.empty() ? kResendAfter : kMessagesAfter);
  return std::max(Clock::duration::zero(), due - now);
}

int CigiFrames::step(Clock::time_point now) {
  if (!host_known_) return 0;
  if (options_.cigi->pacing == CigiPacing::Asynchronous) {
    if (now < next_async_frame_) return 0;
    next_async_frame_ =
        now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / options_.cigi->rate_hz));
    return frame(now);
  }
  if (!waiting_.empty()) {
    cigi::HostDatagram d = std::move(waiting_.front());
    waiting_.pop_front();
    apply(d);
    return frame(now);
  }
  if (wait(now) == Clock::duration::zero()) send_start_of_frame(now);  // the last one again
  return 0;
}

cigi::StartOfFrame CigiFrames::start_of_frame() const {
  cigi::StartOfFrame sof;
  sof.mode = state_.mode();
  sof.ig_frame = ig_frame_;
  sof.last_host_frame = state_.last_host_frame();
  sof.timestamp_valid = true;
  const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
  sof.timestamp = static_cast<std::uint32_t>(static_cast<std::uint64_t>(seconds * cigi::kTimestampTicksPerSecond));
  return sof;
}

void CigiFrames::send_start_of_frame(Clock::time_point now) {
  send_(outbox_.datagram(start_of_frame(), host_order_));
  last_sent_ = now;
}

int CigiFrames::frame(Clock::time_point now) {
  ++ig_frame_;
  update_weather();
  const bool draws = state_.mode() == cigi::IgMode::Operate || state_.mode() == cigi::IgMode::Debug;
  if (draws && !state_.ownship() && !told_no_ownship_) {
    report("no Entity Control of the ownship (entity 0) yet: nothing is drawn");
    told_no_ownship_ = true;
  }
  send_start_of_frame(now);
  if (!draws || !state_.ownship()) return 0;
  return render_views(state_.utc_s().value_or(options_.unix_time_s));
}

void CigiFrames::update_weather() {
  update_cloud_layers();
  update_visibility();
}

void CigiFrames::update_cloud_layers() {
  if (state_.weather_generation() == 0) return;  // no cloud layers from the host: --weather's
  const double lat = state_.ownship() ? state_.ownship()->lat_deg : 0.0;
  const double lon = state_.ownship() ? state_.ownship()->lon_deg : 0.0;
  // Made again when the layers change, or when the ownship comes nearer another region
  // that defines a layer (the layers' types and altitudes are the nearest region's).
  cigi::CloudLayerSet defining = cigi::defining_layers(state_, lat, lon);
  if (state_.weather_generation() == weather_generation_ && defining == defining_layers_) return;
  weather_generation_ = state_.weather_generation();
  defining_layers_ = std::move(defining);
  try {
    cigi::CigiWeather w =
        cigi::cigi_weather(state_, lat, lon, renderer_.weather_map_width(), renderer_.weather_map_height());
    for (const std::string& note : w.notes) report(note);
    renderer_.update_forecast(w.weather, std::move(w.map));  // clouds drift on where winds stay
    weather_taken_();
  } catch (const std::exception& e) {
    report(std::string("the cloud layers cannot be drawn: ") + e.what());
  }
}

void CigiFrames::update_visibility() {
  if (state_.atmosphere_generation() == atmosphere_generation_) return;
  atmosphere_generation_ = state_.atmosphere_generation();
  const cigi::CigiVisibility v = cigi::cigi_visibility(state_);
  if (v.note) report(*v.note);
  if (renderer_.weather().visibility_m == v.visibility_m) return;  // the host's layers, just made, carry it
  weather::Weather w = renderer_.weather();
  w.visibility_m = v.visibility_m;  // m, within the drawn range
  try {
    if (renderer_.has_forecast()) renderer_.update_forecast_layers(w);  // keeps the forecast's maps
    else renderer_.update_weather(w);                                  // the same seed: the same map
  } catch (const std::exception& e) {
    report(std::string("the visibility cannot be drawn: ") + e.what());
  }
}

int CigiFrames::render_views(double utc_s) {
  const cigi::OwnshipPose& ownship = *state_.ownship();
  const std::vector<cigi::View> views = state_.views();
  int rendered = 0;
  for (const cigi::View& v : views) {
    const cigi::ViewPose pose = cigi::view_pose(ownship, v);
    ViewRequest r;
    r.position = pose.position;
    r.attitude = pose.attitude;
    r.unix_time_s = utc_s;
    r.width = options_.width;
    r.height = options_.height;
    r.frustum = ViewFrustumAngles{v.frustum.left_deg, v.frustum.right_deg, v.frustum.bottom_deg, v.frustum.top_deg};
    r.near_m = v.frustum.near_m;  // clouds between the host's planes (0: not given)
    r.far_m = v.frustum.far_m;
    r.channel = kChannelBase + v.id;
    r.frame_index = ig_frame_;
    try {
      // --cigi-quality / --cigi-view-quality (names checked when the options were parsed)
      FrameImage img = renderer_.render(r, *quality_preset(options_.cigi->quality_of(v.id)));
      mirror_image(img, static_cast<MirrorMode>(v.mirror));  // after the render: the history stays unmirrored
      publish(v, pose, img, utc_s, &v == &views.front());
      ++rendered;
    } catch (const std::exception& e) {
      report("IG frame " + std::to_string(ig_frame_) + ", view " + std::to_string(v.id) + ": " + e.what());
    }
  }
  return rendered;
}

void CigiFrames::publish(const cigi::View& v, const cigi::ViewPose& pose, const FrameImage& img, double utc_s,
                         bool first_view) {
  const std::lock_guard publishing(*outputs_.publish_mutex);
  if (outputs_.rings && !ring_failed_.contains(v.id)) {
    try {
      // sim time: the host's timestamp of the frame, 0 when it gave none
      const double sim_time_s = state_.host_timestamp_s().value_or(0.0);
      publish_to_shm(outputs_.rings->ring(v.id), img,
                     shm_frame_meta(ig_frame_, sim_time_s, utc_s, pose.position, pose.attitude, img),
                     protocol::SetView{}.shm_format);
    } catch (const std::exception& e) {
      ring_failed_.insert(v.id);
      report("view " + std::to_string(v.id) + ": no shared-memory ring: " + e.what());
    }
  }
  if (!options_.out_dir.empty()) {
    try {
      const std::filesystem::path dir = std::filesystem::path(options_.out_dir) / ("view" + std::to_string(v.id));
      std::filesystem::create_directories(dir);
      protocol::SetView file_view;
      file_view.file_dir = dir.string();
      file_view.file_format = protocol::FileFormat::Png;
      publish_to_file(img, ig_frame_, file_view, options_.out_dir);
    } catch (const std::exception& e) {
      if (file_failed_.insert(v.id).second)
        report("view " + std::to_string(v.id) + ": frame files: " + e.what() + " (said once per view)");
    }
  }
  if (outputs_.window && first_view) outputs_.window->present(img);
}

}  // namespace cloudsvc
