// A view's frame target (frame_target.h).
#include "renderer/frame_target.h"

namespace cloudsvc {

void FrameTarget::ensure_size(int w, int h) {
  if (texture_ && w == w_ && h == h_) return;
  texture_ = gl::make_texture_2d(GL_RGBA32F, w, h, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  w_ = w;
  h_ = h;
}

void FrameTarget::read_back(FrameImage& img) const {
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  img.width = w_;
  img.height = h_;
  img.rgba.resize(static_cast<size_t>(w_) * h_ * 4);
  glGetTextureImage(texture_.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(img.rgba.size() * sizeof(float)),
                    img.rgba.data());
}

}  // namespace cloudsvc
