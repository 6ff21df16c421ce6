// Dispatch of a compute pass over a w x h (x d) grid of invocations in 8 x 8 groups (the
// local size of every 2-D pass), followed by the barrier that makes its image writes
// visible to texture fetches and image loads of the passes after it.
#pragma once

#include <epoxy/gl.h>

namespace cloudsvc::gl {

inline void dispatch_2d(int w, int h, int d = 1) {
  glDispatchCompute(static_cast<GLuint>((w + 7) / 8), static_cast<GLuint>((h + 7) / 8), static_cast<GLuint>(d));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace cloudsvc::gl
