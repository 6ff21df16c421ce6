#include "service/render_loop.h"

#include <chrono>
#include <exception>
#include <memory>
#include <string>

#include "protocol/limits.h"
#include "protocol/shm/shm_frame_writer.h"
#include "protocol/weather_conversion.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/quality_presets.h"
#include "service/cigi_frames.h"
#include "service/forecast_tracker.h"
#include "service/frame_sinks.h"
#include "service/sim_clock.h"
#include "service/window_presenter.h"

namespace cloudsvc {

namespace {

using SteadyClock = std::chrono::steady_clock;

std::int64_t steady_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(SteadyClock::now().time_since_epoch()).count();
}

ViewRequest view_request(const protocol::Pose& p, double utc_s, const protocol::SetView& v, std::uint64_t frame) {
  ViewRequest r;
  r.position = {p.lat_deg, p.lon_deg, p.alt_m};
  r.attitude = {p.heading_deg, p.pitch_deg, p.roll_deg};
  r.unix_time_s = utc_s;
  r.fov_deg = v.hfov_deg;
  r.width = static_cast<int>(v.width);
  r.height = static_cast<int>(v.height);
  r.frame_index = static_cast<std::uint32_t>(frame);
  // a teleport or sim reset: no temporal history, no shadow map from before the jump
  r.reset_history = (p.flags & protocol::pose_flag::kAll) != 0;
  return r;
}

bool utc_in_range(double utc_s) { return utc_s >= protocol::kMinUtc_s && utc_s < protocol::kMaxUtc_s; }

// Where the answers about one frame go: a pose-driven frame to every client (reply_to
// empty, request_id 0), a requested one to the requester; an Error about the frame
// answers `answers_seq`.
struct FrameAddress {
  std::uint64_t request_id = 0;
  std::optional<std::uint64_t> reply_to;
  std::uint64_t answers_seq = 0;
};

}  // namespace

RendererConfig renderer_config(const ServeOptions& o) {
  RendererConfig c;
  c.cumulus_domes = o.cumulus_domes;
  c.noise_tiling = o.noise_tiling;
  c.cloud_phase = o.cloud_phase;
  c.wait_for_phase_tables = false;  // a new droplet size's Mie table must not stall the frames
  return c;
}

protocol::SetView initial_view(const ServeOptions& o) {
  protocol::SetView v;
  v.width = static_cast<std::uint32_t>(o.width);
  v.height = static_cast<std::uint32_t>(o.height);
  v.hfov_deg = o.fov_deg;
  v.sinks = 0;
  if (!o.shm_name.empty()) v.sinks |= protocol::sink::kShm;
  if (!o.out_dir.empty()) v.sinks |= protocol::sink::kFile;
  if (o.window) v.sinks |= protocol::sink::kWindow;
  v.file_dir = o.out_dir;
  v.file_format = protocol::FileFormat::Png;
  return v;
}

RenderLoop::RenderLoop(const ServeOptions& options, FrameMailbox& mailbox, Notify notify, StopService stop_service,
                       ShmFrameWriter* shm, std::mutex& publish_mutex, SendCigi send_cigi, ViewRings* view_rings)
    : options_(options), mailbox_(mailbox), notify_(std::move(notify)), stop_service_(std::move(stop_service)),
      shm_(shm), publish_mutex_(publish_mutex), send_cigi_(std::move(send_cigi)), view_rings_(view_rings) {}

double RenderLoop::frame_in_progress_ms() const {
  const std::int64_t started = frame_started_ns_.load();
  return started == 0 ? 0.0 : static_cast<double>(steady_ns() - started) * 1e-6;
}

class RenderLoop::Run {
 public:
  // Makes the GL context (the window's when there is one, else headless EGL) and then the
  // renderer, with the command line's weather, view and time.
  explicit Run(RenderLoop& loop);

  // How long a take() of the mailbox waits: a window needs its events polled, a CIGI host
  // its frames.
  std::chrono::milliseconds wait() const;
  // Processes the window's events; its close button stops the service.
  void poll_window();
  void apply_change(StateChange& c);
  // The newest pose: rendered and announced to everyone when its UTC is in range.
  void on_pose(const PendingPose& p);
  // A RenderRequest: the pose on screen rendered again for the requester.
  void on_render_request(const PendingRender& r);
  // A CIGI host's datagrams, then the CIGI frame that is due, if any.
  void on_cigi(MailboxBatch& batch);

 private:
  void apply_tile(const protocol::WeatherMapTile& tile);
  // The steps of one frame, in order.
  void render_and_publish(const PendingPose& p, const FrameAddress& to);
  std::optional<FrameImage> render_frame(const PendingPose& p, double utc_s, const FrameAddress& to);
  void publish_to_sinks(const FrameImage& img, const PendingPose& p, double utc_s, protocol::FrameReady& ready,
                        const FrameAddress& to);
  void announce(protocol::FrameReady& ready, const PendingPose& p, const FrameAddress& to);
  // One more frame (a client's or an IG frame).
  void count_frame();
  // After the frame's notices: the last frame --exit-after-frames allows stops the service.
  void stop_after_last_frame();

  RenderLoop& loop_;
  const ServeOptions& options_;
  // Declared before the renderer: its GL context exists first and goes last.
  std::unique_ptr<WindowPresenter> window_;
  std::unique_ptr<gl::EglContext> egl_;
  CloudRenderer renderer_;
  protocol::SetView view_;
  SimClock clock_;
  std::unique_ptr<ForecastTracker> forecast_;  // --weather FILE.grib2|.metar, until a client sends layers
  std::optional<PendingPose> pose_;  // the pose on screen
  std::uint64_t frame_ = 0;          // client frames begun, numbering them from 1
  std::uint64_t frames_done_ = 0;    // client and IG frames rendered
  std::unique_ptr<CigiFrames> cigi_;  // --cigi
  SteadyClock::time_point fps_window_start_;
  std::uint64_t fps_window_frames_ = 0;
};

RenderLoop::Run::Run(RenderLoop& loop)
    : loop_(loop), options_(loop.options_),
      window_(options_.window ? std::make_unique<WindowPresenter>(options_.width, options_.height, "cloudsvc serve")
                              : nullptr),
      egl_(window_ ? nullptr : std::make_unique<gl::EglContext>()), renderer_(renderer_config(options_)),
      view_(initial_view(options_)) {
  if (options_.forecast)
    forecast_ = std::make_unique<ForecastTracker>(options_.forecast, renderer_.weather_map_width(),
                                                  renderer_.weather_map_height(), options_.unix_time_s);
  else
    renderer_.set_weather(options_.weather);
  clock_.set(options_.unix_time_s);
  fps_window_start_ = SteadyClock::now();
  if (options_.cigi)
    cigi_ = std::make_unique<CigiFrames>(options_, renderer_,
                                         CigiFrames::Outputs{loop_.view_rings_, window_.get(), &loop_.publish_mutex_},
                                         loop_.send_cigi_, [this] { forecast_.reset(); });
}

std::chrono::milliseconds RenderLoop::Run::wait() const {
  std::chrono::milliseconds w(window_ ? 30 : 200);
  if (cigi_)
    w = std::min(w, std::chrono::ceil<std::chrono::milliseconds>(cigi_->wait(SteadyClock::now())));
  return w;
}

void RenderLoop::Run::on_cigi(MailboxBatch& batch) {
  if (!cigi_) return;
  if (!batch.cigi.empty() || batch.cigi_refused > 0) cigi_->receive(std::move(batch.cigi), batch.cigi_refused);
  loop_.frame_started_ns_.store(steady_ns());
  const int views = cigi_->step(SteadyClock::now());
  loop_.frame_started_ns_.store(0);
  loop_.cigi_rejections_.store(cigi_->packets_rejected());
  if (views > 0) {
    count_frame();
    stop_after_last_frame();
  }
}

void RenderLoop::Run::poll_window() {
  if (!window_) return;
  window_->poll();
  if (window_->close_requested()) loop_.stop_service_();
}

void RenderLoop::Run::apply_change(StateChange& c) {
  if (auto* v = std::get_if<protocol::SetView>(&c)) view_ = *v;
  else if (auto* w = std::get_if<protocol::WeatherLayers>(&c)) {
    renderer_.update_weather(to_weather(*w));  // a client's layers replace the forecast; resent ones change nothing
    forecast_.reset();
  }
  else if (auto* t = std::get_if<protocol::SetTime>(&c)) clock_.set(t->utc_unix_s);
  else if (auto* tile = std::get_if<protocol::WeatherMapTile>(&c)) apply_tile(*tile);
}

void RenderLoop::Run::apply_tile(const protocol::WeatherMapTile& tile) {
  // "now" is the time of the pose on screen.
  const double now = pose_ ? clock_.utc_for(pose_->pose) : clock_.base_utc_s();
  try {
    renderer_.apply_tile(to_map_tile(tile), now);
  } catch (const std::exception& e) {
    // The protocol checked the tile with the rules apply_tile checks again (one rule set,
    // weather/map_tile.h), so this is a safety net only.
    loop_.notify_(std::nullopt, protocol::Error{protocol::ErrorCode::InvalidField, e.what(), 0});
  }
  loop_.mailbox_.tile_applied(tile);
}

void RenderLoop::Run::on_pose(const PendingPose& p) {
  // A pose without its own UTC gets one from the clock (SetTime + sim time since); checked
  // like an explicit UTC, so e.g. sim_time_s 1e300 is refused, not drawn black.
  const double utc = clock_.utc_for(p.pose);
  if (!utc_in_range(utc)) {
    loop_.notify_(p.client_id,
                  protocol::Error{protocol::ErrorCode::InvalidField,
                                  "Pose.sim_time_s: the pose's UTC (last SetTime advanced by sim time since) is " +
                                      std::to_string(utc) + " s, outside [" + std::to_string(protocol::kMinUtc_s) +
                                      ", " + std::to_string(protocol::kMaxUtc_s) +
                                      ") (years 1900-2199); pose not rendered",
                                  p.seq});
    return;
  }
  clock_.observe(p.pose);
  pose_ = p;
  if (forecast_) forecast_->update(renderer_, p.pose.lat_deg, p.pose.lon_deg, utc);
  render_and_publish(*pose_, FrameAddress{});
}

void RenderLoop::Run::on_render_request(const PendingRender& r) {
  if (!pose_) {
    loop_.notify_(r.client_id, protocol::Error{protocol::ErrorCode::UnexpectedMessage,
                                               "RenderRequest before any Pose: nothing to render", r.seq});
  } else {
    PendingPose p = *pose_;
    p.received = r.received;
    render_and_publish(p, FrameAddress{r.request_id, r.client_id, r.seq});
  }
  loop_.mailbox_.render_finished(r.client_id);
}

void RenderLoop::Run::render_and_publish(const PendingPose& p, const FrameAddress& to) {
  const double utc = clock_.utc_for(p.pose);
  ++frame_;  // a frame that fails to render keeps its number
  const std::optional<FrameImage> img = render_frame(p, utc, to);
  if (!img) return;
  protocol::FrameReady ready;
  ready.frame_number = frame_;
  ready.request_id = to.request_id;
  ready.pose = p.pose;
  ready.sim_time_s = p.pose.sim_time_s;
  ready.width = view_.width;
  ready.height = view_.height;
  ready.render_ms = img->stats.render_ms;
  publish_to_sinks(*img, p, utc, ready, to);
  announce(ready, p, to);
}

// The frame's image, or nullopt after an Error{RenderFailed} went to `to`.
std::optional<FrameImage> RenderLoop::Run::render_frame(const PendingPose& p, double utc_s, const FrameAddress& to) {
  loop_.frame_started_ns_.store(steady_ns());
  try {
    const std::string preset = view_.quality_preset.empty() ? "default" : view_.quality_preset;
    // the preset's name was checked by check_view
    FrameImage img = renderer_.render(view_request(p.pose, utc_s, view_, frame_), *quality_preset(preset));
    loop_.frame_started_ns_.store(0);
    return img;
  } catch (const std::exception& e) {
    loop_.frame_started_ns_.store(0);
    loop_.notify_(to.reply_to, protocol::Error{protocol::ErrorCode::RenderFailed, e.what(), to.answers_seq});
    return std::nullopt;
  }
}

// Writes the frame to every sink the view asks for (service/frame_sinks.h), all under the
// publish mutex, and fills in where it went. A file that cannot be written is reported to
// `to` (SinkUnavailable); the frame is still announced.
void RenderLoop::Run::publish_to_sinks(const FrameImage& img, const PendingPose& p, double utc_s,
                                       protocol::FrameReady& ready, const FrameAddress& to) {
  const std::lock_guard publishing(loop_.publish_mutex_);
  if ((view_.sinks & protocol::sink::kShm) && loop_.shm_) {
    ready.shm_slot = publish_to_shm(*loop_.shm_, img, shm_frame_meta(frame_, p.pose, utc_s, img), view_.shm_format);
  }
  if ((view_.sinks & protocol::sink::kFile) && !view_.file_dir.empty()) {
    try {
      ready.file_path = publish_to_file(img, frame_, view_, options_.out_dir);
    } catch (const std::exception& e) {
      loop_.notify_(to.reply_to, protocol::Error{protocol::ErrorCode::SinkUnavailable, e.what(), to.answers_seq});
    }
  }
  if ((view_.sinks & protocol::sink::kWindow) && window_) window_->present(img);
}

// FrameReady to `to`, after the counters.
void RenderLoop::Run::announce(protocol::FrameReady& ready, const PendingPose& p, const FrameAddress& to) {
  ready.latency_ms = std::chrono::duration<double, std::milli>(SteadyClock::now() - p.received).count();
  count_frame();
  loop_.notify_(to.reply_to, ready);
  stop_after_last_frame();
}

void RenderLoop::Run::stop_after_last_frame() {
  if (options_.exit_after_frames > 0 && frames_done_ >= static_cast<std::uint64_t>(options_.exit_after_frames))
    loop_.stop_service_();
}

void RenderLoop::Run::count_frame() {
  loop_.frames_.store(++frames_done_);
  ++fps_window_frames_;
  const auto now = SteadyClock::now();
  const double span = std::chrono::duration<double>(now - fps_window_start_).count();
  if (span >= 1.0) {
    loop_.fps_.store(static_cast<double>(fps_window_frames_) / span);
    fps_window_start_ = now;
    fps_window_frames_ = 0;
  }
}

void RenderLoop::run() {
  Run run(*this);
  for (;;) {
    MailboxBatch batch = mailbox_.take(run.wait());
    if (batch.stop) break;  // no new frame once the service is stopping
    run.poll_window();
    for (StateChange& c : batch.changes) run.apply_change(c);
    if (batch.pose) run.on_pose(*batch.pose);
    for (const PendingRender& r : batch.renders) run.on_render_request(r);
    run.on_cigi(batch);
  }
}

}  // namespace cloudsvc
