// A GLFW window with an OpenGL 4.5 core context that shows tone-mapped frames. Used by
// `cloudsvc render --window` and `cloudsvc serve --window`. The window's context is the
// renderer's context: create the presenter first, then the CloudRenderer, on one thread.
#pragma once

#include <memory>
#include <string>

#include "renderer/api/frame_image.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"

struct GLFWwindow;

namespace cloudsvc {

class WindowPresenter {
 public:
  // Opens the window and makes its context current. Throws std::runtime_error (no
  // display: run under xvfb-run or set DISPLAY).
  WindowPresenter(int width, int height, const std::string& title);
  ~WindowPresenter();
  WindowPresenter(const WindowPresenter&) = delete;
  WindowPresenter& operator=(const WindowPresenter&) = delete;

  // Tone-maps img and shows it (resizing the window's image to the frame).
  void present(const FrameImage& img, double exposure_ev = 0.0);
  // Redraws the last frame and processes window events without blocking.
  void poll();
  void set_title(const std::string& title);
  bool close_requested() const;
  GLFWwindow* window() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cloudsvc
