// The render thread of `cloudsvc serve`: owns the GL context and the renderer (DESIGN.md
// §1), takes batches from the FrameMailbox, applies state changes in order, renders the
// newest pose, and hands each frame to the sinks (shared-memory ring, files, window)
// before announcing it with FrameReady.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>

#include "protocol/messages.h"
#include "service/frame_mailbox.h"
#include "service/serve_options.h"

namespace cloudsvc {

class RenderLoop {
 public:
  // Called on the render thread; must hand the message to the network thread.
  // client == nullopt: broadcast to every client.
  using Notify = std::function<void(std::optional<std::uint64_t> client, protocol::Message m)>;
  using StopService = std::function<void()>;

  RenderLoop(const ServeOptions& options, FrameMailbox& mailbox, Notify notify, StopService stop_service);

  // Runs until the mailbox says stop (finishes the frame in progress first). Throws
  // std::runtime_error when the GL context or a sink cannot be created.
  void run();

  std::uint64_t frames_rendered() const { return frames_.load(); }
  double fps() const { return fps_.load(); }

 private:
  const ServeOptions& options_;
  FrameMailbox& mailbox_;
  Notify notify_;
  StopService stop_service_;
  std::atomic<std::uint64_t> frames_{0};
  std::atomic<double> fps_{0.0};
};

// The initial view of a service: sinks from the command line (shm if --shm, file if
// --out-dir, window if --window), size and fov from --size/--fov.
protocol::SetView initial_view(const ServeOptions& options);

}  // namespace cloudsvc
