#include "service/render_loop.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "protocol/limits.h"
#include "protocol/shm/shm_frame_writer.h"
#include "protocol/weather_conversion.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/image_output.h"
#include "renderer/quality_presets.h"
#include "service/frame_encoding.h"
#include "service/output_directory.h"
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

}  // namespace

void SimClock::set(double utc_s) {
  base_utc_s_ = utc_s;
  base_sim_s_.reset();
}

double SimClock::utc_for(const protocol::Pose& p) const {
  if (p.utc_unix_s) return *p.utc_unix_s;
  return base_utc_s_ + (base_sim_s_ ? p.sim_time_s - *base_sim_s_ : 0.0);
}

void SimClock::observe(const protocol::Pose& p) {
  if (p.utc_unix_s) {
    base_utc_s_ = *p.utc_unix_s;
    base_sim_s_ = p.sim_time_s;
  } else if (!base_sim_s_) {
    base_sim_s_ = p.sim_time_s;
  }
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
                       ShmFrameWriter* shm, std::mutex& publish_mutex)
    : options_(options), mailbox_(mailbox), notify_(std::move(notify)), stop_service_(std::move(stop_service)),
      shm_(shm), publish_mutex_(publish_mutex) {}

double RenderLoop::frame_in_progress_ms() const {
  const std::int64_t started = frame_started_ns_.load();
  return started == 0 ? 0.0 : static_cast<double>(steady_ns() - started) * 1e-6;
}

void RenderLoop::run() {
  // GL context: the window's when there is one, else headless EGL.
  std::unique_ptr<WindowPresenter> window;
  std::unique_ptr<gl::EglContext> egl;
  if (options_.window) window = std::make_unique<WindowPresenter>(options_.width, options_.height, "cloudsvc serve");
  else egl = std::make_unique<gl::EglContext>();

  CloudRenderer renderer;
  renderer.set_weather(options_.weather);
  protocol::SetView view = initial_view(options_);
  SimClock clock;
  clock.set(options_.unix_time_s);
  std::optional<PendingPose> pose;  // the pose on screen
  std::uint64_t frame = 0;
  auto fps_window_start = SteadyClock::now();
  std::uint64_t fps_window_frames = 0;

  // Writes the frame to every sink the view asks for; fills in where it went.
  auto publish = [&](const FrameImage& img, const PendingPose& p, double utc, protocol::FrameReady& ready,
                     std::optional<std::uint64_t> reply_to, std::uint64_t answers_seq) {
    const std::lock_guard publishing(publish_mutex_);
    if ((view.sinks & protocol::sink::kShm) && shm_) {
      ShmFrameMeta meta{frame, p.pose.sim_time_s, utc, p.pose.lat_deg, p.pose.lon_deg, p.pose.alt_m,
                        p.pose.heading_deg, p.pose.pitch_deg, p.pose.roll_deg, img.stats.render_ms};
      if (view.shm_format == protocol::ShmPixelFormat::Rgba8Srgb) {
        const auto px = to_rgba8_srgb(img);
        ready.shm_slot = shm_->write(meta, CLOUDSVC_SHM_RGBA8_SRGB, img.width, img.height, px.data(),
                                     static_cast<std::size_t>(img.width) * 4);
      } else {
        const auto px = to_rgba16f(img);
        ready.shm_slot = shm_->write(meta, CLOUDSVC_SHM_RGBA16F_LINEAR, img.width, img.height, px.data(),
                                     static_cast<std::size_t>(img.width) * 8);
      }
    }
    if ((view.sinks & protocol::sink::kFile) && !view.file_dir.empty()) {
      // Checked again for every frame: a directory accepted earlier may since have been
      // replaced by a link leading out of --out-dir.
      const ClientDirectory dir = resolve_client_directory(view.file_dir, options_.out_dir);
      char name[64];
      std::snprintf(name, sizeof name, "frame_%06llu.%s", static_cast<unsigned long long>(frame),
                    view.file_format == protocol::FileFormat::Exr ? "exr" : "png");
      try {
        if (!dir.problem.empty()) throw std::runtime_error(dir.problem);
        const std::string path = (dir.path / name).string();
        write_image(path, img);
        ready.file_path = path;
      } catch (const std::exception& e) {
        notify_(reply_to, protocol::Error{protocol::ErrorCode::SinkUnavailable, e.what(), answers_seq});
      }
    }
    if ((view.sinks & protocol::sink::kWindow) && window) window->present(img);
  };

  auto count_frame = [&] {
    frames_.store(frame);
    ++fps_window_frames;
    const auto now = SteadyClock::now();
    const double span = std::chrono::duration<double>(now - fps_window_start).count();
    if (span >= 1.0) {
      fps_.store(static_cast<double>(fps_window_frames) / span);
      fps_window_start = now;
      fps_window_frames = 0;
    }
  };

  // Renders p and announces it: pose-driven frames to everyone (reply_to empty), requested
  // frames to the requester; an Error about the frame answers `answers_seq`.
  auto render_and_publish = [&](const PendingPose& p, std::uint64_t request_id, std::optional<std::uint64_t> reply_to,
                                std::uint64_t answers_seq) {
    const double utc = clock.utc_for(p.pose);
    ++frame;
    FrameImage img;
    frame_started_ns_.store(steady_ns());
    try {
      const std::string preset = view.quality_preset.empty() ? "default" : view.quality_preset;
      img = renderer.render(view_request(p.pose, utc, view, frame), *quality_preset(preset));  // checked by check_view
    } catch (const std::exception& e) {
      frame_started_ns_.store(0);
      notify_(reply_to, protocol::Error{protocol::ErrorCode::RenderFailed, e.what(), answers_seq});
      return;
    }
    frame_started_ns_.store(0);
    protocol::FrameReady ready;
    ready.frame_number = frame;
    ready.request_id = request_id;
    ready.pose = p.pose;
    ready.sim_time_s = p.pose.sim_time_s;
    ready.width = view.width;
    ready.height = view.height;
    ready.render_ms = img.stats.render_ms;
    publish(img, p, utc, ready, reply_to, answers_seq);
    ready.latency_ms = std::chrono::duration<double, std::milli>(SteadyClock::now() - p.received).count();
    count_frame();
    notify_(reply_to, ready);
    if (options_.exit_after_frames > 0 && frame >= static_cast<std::uint64_t>(options_.exit_after_frames))
      stop_service_();
  };

  auto apply_change = [&](StateChange& c) {
    if (auto* v = std::get_if<protocol::SetView>(&c)) view = *v;
    else if (auto* w = std::get_if<protocol::WeatherLayers>(&c)) renderer.set_weather(to_weather(*w));
    else if (auto* t = std::get_if<protocol::SetTime>(&c)) clock.set(t->utc_unix_s);
    else if (auto* tile = std::get_if<protocol::WeatherMapTile>(&c)) {
      // Validated by the protocol; "now" is the time of the pose on screen.
      const double now = pose ? clock.utc_for(pose->pose) : clock.base_utc_s();
      try {
        renderer.apply_tile(to_map_tile(*tile), now);
      } catch (const std::exception& e) {  // the protocol validated it: a safety net only
        notify_(std::nullopt, protocol::Error{protocol::ErrorCode::InvalidField, e.what(), 0});
      }
      mailbox_.tile_applied(*tile);
    }
  };

  for (;;) {
    MailboxBatch batch = mailbox_.take(std::chrono::milliseconds(window ? 30 : 200));
    if (batch.stop) break;  // no new frame once the service is stopping
    if (window) {
      window->poll();
      if (window->close_requested()) stop_service_();
    }
    for (StateChange& c : batch.changes) apply_change(c);
    if (batch.pose) {
      // A pose without its own UTC gets one from the clock (SetTime + sim time since);
      // checked like an explicit UTC, so e.g. sim_time_s 1e300 is refused, not drawn black.
      const double utc = clock.utc_for(batch.pose->pose);
      if (!utc_in_range(utc)) {
        notify_(batch.pose->client_id,
                protocol::Error{protocol::ErrorCode::InvalidField,
                                "Pose.sim_time_s: the pose's UTC (last SetTime advanced by sim time since) is " +
                                    std::to_string(utc) + " s, outside [" + std::to_string(protocol::kMinUtc_s) + ", " +
                                    std::to_string(protocol::kMaxUtc_s) + ") (years 1900-2199); pose not rendered",
                                batch.pose->seq});
      } else {
        clock.observe(batch.pose->pose);
        pose = batch.pose;
        render_and_publish(*pose, 0, std::nullopt, 0);
      }
    }
    for (const PendingRender& r : batch.renders) {
      if (!pose) {
        notify_(r.client_id, protocol::Error{protocol::ErrorCode::UnexpectedMessage,
                                             "RenderRequest before any Pose: nothing to render", r.seq});
      } else {
        PendingPose p = *pose;
        p.received = r.received;
        render_and_publish(p, r.request_id, r.client_id, r.seq);
      }
      mailbox_.render_finished(r.client_id);
    }
  }
}

}  // namespace cloudsvc
