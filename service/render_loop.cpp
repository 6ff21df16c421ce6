#include "service/render_loop.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/image_output.h"
#include "renderer/quality_presets.h"
#include "service/frame_encoding.h"
#include "protocol/weather_conversion.h"
#include "service/shm_frame_writer.h"
#include "service/window_presenter.h"

namespace cloudsvc {

namespace {

// UTC of a pose: its own, else the last SetTime advanced by simulation time since then.
struct SimClock {
  double base_utc_s = 0.0;
  std::optional<double> base_sim_s;  // sim time of the first pose after the base was set

  double utc_for(const protocol::Pose& p) {
    if (p.utc_unix_s) {
      base_utc_s = *p.utc_unix_s;
      base_sim_s = p.sim_time_s;
      return *p.utc_unix_s;
    }
    if (!base_sim_s) base_sim_s = p.sim_time_s;
    return base_utc_s + (p.sim_time_s - *base_sim_s);
  }
  void set(double utc_s) {
    base_utc_s = utc_s;
    base_sim_s.reset();
  }
};

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

}  // namespace

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

RenderLoop::RenderLoop(const ServeOptions& options, FrameMailbox& mailbox, Notify notify, StopService stop_service)
    : options_(options), mailbox_(mailbox), notify_(std::move(notify)), stop_service_(std::move(stop_service)) {}

void RenderLoop::run() {
  // GL context: the window's when there is one, else headless EGL.
  std::unique_ptr<WindowPresenter> window;
  std::unique_ptr<gl::EglContext> egl;
  if (options_.window) window = std::make_unique<WindowPresenter>(options_.width, options_.height, "cloudsvc serve");
  else egl = std::make_unique<gl::EglContext>();
  std::unique_ptr<ShmFrameWriter> shm;
  if (!options_.shm_name.empty())
    shm = std::make_unique<ShmFrameWriter>(options_.shm_name, options_.shm_max_width, options_.shm_max_height);

  CloudRenderer renderer;
  renderer.set_weather(options_.weather);
  protocol::SetView view = initial_view(options_);
  SimClock clock;
  clock.set(options_.unix_time_s);
  std::optional<PendingPose> pose;  // the pose on screen
  std::uint64_t frame = 0;
  auto fps_window_start = std::chrono::steady_clock::now();
  std::uint64_t fps_window_frames = 0;

  auto render_and_publish = [&](const PendingPose& p, std::uint64_t request_id, std::optional<std::uint64_t> reply_to) {
    ++frame;
    const double utc = clock.utc_for(p.pose);
    FrameImage img;
    try {
      const std::string preset = view.quality_preset.empty() ? "default" : view.quality_preset;
      img = renderer.render(view_request(p.pose, utc, view, frame), *quality_preset(preset));  // checked by check_view
    } catch (const std::exception& e) {
      notify_(reply_to, protocol::Error{protocol::ErrorCode::RenderFailed, e.what(), 0});
      return;
    }
    protocol::FrameReady ready;
    ready.frame_number = frame;
    ready.request_id = request_id;
    ready.pose = p.pose;
    ready.sim_time_s = p.pose.sim_time_s;
    ready.width = view.width;
    ready.height = view.height;
    ready.render_ms = img.stats.render_ms;
    if ((view.sinks & protocol::sink::kShm) && shm) {
      ShmFrameMeta meta{frame, p.pose.sim_time_s, utc, p.pose.lat_deg, p.pose.lon_deg, p.pose.alt_m,
                        p.pose.heading_deg, p.pose.pitch_deg, p.pose.roll_deg, img.stats.render_ms};
      if (view.shm_format == protocol::ShmPixelFormat::Rgba8Srgb) {
        const auto px = to_rgba8_srgb(img);
        ready.shm_slot = shm->write(meta, CLOUDSVC_SHM_RGBA8_SRGB, img.width, img.height, px.data(),
                                    static_cast<std::size_t>(img.width) * 4);
      } else {
        const auto px = to_rgba16f(img);
        ready.shm_slot = shm->write(meta, CLOUDSVC_SHM_RGBA16F_LINEAR, img.width, img.height, px.data(),
                                    static_cast<std::size_t>(img.width) * 8);
      }
    }
    if ((view.sinks & protocol::sink::kFile) && !view.file_dir.empty()) {
      char name[64];
      std::snprintf(name, sizeof name, "frame_%06llu.%s", static_cast<unsigned long long>(frame),
                    view.file_format == protocol::FileFormat::Exr ? "exr" : "png");
      const std::string path = (std::filesystem::path(view.file_dir) / name).string();
      try {
        write_image(path, img);
        ready.file_path = path;
      } catch (const std::exception& e) {
        notify_(reply_to, protocol::Error{protocol::ErrorCode::SinkUnavailable, e.what(), 0});
      }
    }
    if ((view.sinks & protocol::sink::kWindow) && window) window->present(img);
    ready.latency_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - p.received).count();
    frames_.store(frame);
    ++fps_window_frames;
    const auto now = std::chrono::steady_clock::now();
    const double span = std::chrono::duration<double>(now - fps_window_start).count();
    if (span >= 1.0) {
      fps_.store(static_cast<double>(fps_window_frames) / span);
      fps_window_start = now;
      fps_window_frames = 0;
    }
    notify_(reply_to, ready);  // pose-driven frames: everyone; requested frames: the requester
    if (options_.exit_after_frames > 0 && frame >= static_cast<std::uint64_t>(options_.exit_after_frames))
      stop_service_();
  };

  for (;;) {
    MailboxBatch batch = mailbox_.take(std::chrono::milliseconds(window ? 30 : 200));
    if (window) {
      window->poll();
      if (window->close_requested()) stop_service_();
    }
    for (StateChange& c : batch.changes) {
      if (auto* v = std::get_if<protocol::SetView>(&c)) view = *v;
      else if (auto* w = std::get_if<protocol::WeatherLayers>(&c)) renderer.set_weather(to_weather(*w));
      else if (auto* t = std::get_if<protocol::SetTime>(&c)) clock.set(t->utc_unix_s);
      else if (auto* tile = std::get_if<protocol::WeatherMapTile>(&c)) {
        // Validated by the protocol; "now" is the time of the pose on screen.
        const double now = pose ? clock.utc_for(pose->pose) : clock.base_utc_s;
        try {
          renderer.apply_tile(to_map_tile(*tile), now);
        } catch (const std::exception& e) {  // the protocol validated it: a safety net only
          notify_(std::nullopt, protocol::Error{protocol::ErrorCode::InvalidField, e.what(), 0});
        }
      }
    }
    if (batch.pose) {
      pose = batch.pose;
      render_and_publish(*pose, 0, std::nullopt);
    }
    for (const PendingRender& r : batch.renders) {
      if (!pose) {
        notify_(r.client_id, protocol::Error{protocol::ErrorCode::UnexpectedMessage,
                                             "RenderRequest before any Pose: nothing to render", 0});
        continue;
      }
      PendingPose p = *pose;
      p.received = r.received;
      render_and_publish(p, r.request_id, r.client_id);
    }
    if (batch.stop) break;
  }
}

}  // namespace cloudsvc
