// The full-resolution frame a view is composited into (CompositePass) and read back from.
// One per channel (ViewRequest::channel): views of a multi-view display each keep theirs.
// Needs a current GL 4.5 context.
#pragma once

#include <cstddef>

#include "renderer/api/frame_image.h"
#include "renderer/gl/gl_objects.h"

namespace cloudsvc {

class FrameTarget {
 public:
  // Sizes the target (w x h pixels, rgba float).
  void ensure_size(int w, int h);
  int width() const { return w_; }
  int height() const { return h_; }
  const gl::Texture& texture() const { return texture_; }
  // The target into img (rgba float, rows from the top; sets width and height).
  void read_back(FrameImage& img) const;
  std::size_t gpu_bytes() const { return static_cast<std::size_t>(w_) * h_ * 16; }

 private:
  gl::Texture texture_;
  int w_ = 0, h_ = 0;
};

}  // namespace cloudsvc
