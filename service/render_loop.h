// The render thread of `cloudsvc serve`: owns the GL context and the renderer, takes
// batches from the FrameMailbox, applies state changes in order, renders the
// newest pose, and hands each frame to the sinks (shared-memory ring, files, window)
// before announcing it with FrameReady.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <vector>

#include "protocol/messages.h"
#include "service/frame_mailbox.h"
#include "service/serve_options.h"

namespace cloudsvc {

class ShmFrameWriter;
class ViewRings;

class RenderLoop {
 public:
  // Called on the render thread; must hand the message to the network thread.
  // client == nullopt: broadcast to every client.
  using Notify = std::function<void(std::optional<std::uint64_t> client, protocol::Message m)>;
  using StopService = std::function<void()>;

  // `shm` (may be null) is the ring the frames go to when the view asks for it. Every
  // write to a sink (ring, file, window) happens while `publish_mutex` is held, so whoever
  // holds it knows no frame is half published (serve abandons a frame that way).
  // options.out_dir must be canonical: the file sink's directories are checked against it.
  // With --cigi: `send_cigi` hands an IG -> host datagram to the network thread, and
  // `view_rings` (may be null: no --shm) holds the CIGI views' rings (service/cigi_frames.h).
  using SendCigi = std::function<void(std::vector<std::uint8_t>)>;
  RenderLoop(const ServeOptions& options, FrameMailbox& mailbox, Notify notify, StopService stop_service,
             ShmFrameWriter* shm, std::mutex& publish_mutex, SendCigi send_cigi = {}, ViewRings* view_rings = nullptr);

  // Runs until the mailbox says stop; a pose or request still pending then is not
  // rendered. Throws std::runtime_error when the GL context or the window cannot be made.
  void run();

  std::uint64_t frames_rendered() const { return frames_.load(); }
  double fps() const { return fps_.load(); }
  // With --cigi: packets and datagrams of the host not used (each answered with an IG Message).
  std::uint64_t cigi_rejections() const { return cigi_rejections_.load(); }
  // Milliseconds spent so far on the frame being rendered, 0 when none is.
  double frame_in_progress_ms() const;

 private:
  // One run(): the GL context, the renderer, the view, the clock and the frame counter,
  // with the steps of a frame (render, publish to each sink, announce). render_loop.cpp.
  class Run;

  const ServeOptions& options_;
  FrameMailbox& mailbox_;
  Notify notify_;
  StopService stop_service_;
  ShmFrameWriter* shm_;
  std::mutex& publish_mutex_;
  SendCigi send_cigi_;
  ViewRings* view_rings_;
  std::atomic<std::uint64_t> frames_{0};
  std::atomic<double> fps_{0.0};
  std::atomic<std::uint64_t> cigi_rejections_{0};
  std::atomic<std::int64_t> frame_started_ns_{0};  // steady clock; 0 = idle
};

// The initial view of a service: sinks from the command line (shm if --shm, file if
// --out-dir, window if --window), size and fov from --size/--fov.
protocol::SetView initial_view(const ServeOptions& options);

}  // namespace cloudsvc
