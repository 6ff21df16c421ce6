// Owning wrappers for OpenGL object names (textures, buffers). Move-only.
#pragma once

#include <epoxy/gl.h>

#include <utility>

namespace cloudsvc::gl {

template <void (*Delete)(GLsizei, const GLuint*)>
class GlName {
 public:
  GlName() = default;
  explicit GlName(GLuint id) : id_(id) {}
  ~GlName() { reset(); }
  GlName(GlName&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  GlName& operator=(GlName&& o) noexcept {
    if (this != &o) { reset(); id_ = std::exchange(o.id_, 0); }
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() { if (id_) { Delete(1, &id_); id_ = 0; } }

 private:
  GLuint id_ = 0;
};

inline void delete_textures(GLsizei n, const GLuint* ids) { glDeleteTextures(n, ids); }
inline void delete_buffers(GLsizei n, const GLuint* ids) { glDeleteBuffers(n, ids); }
inline void delete_vertex_arrays(GLsizei n, const GLuint* ids) { glDeleteVertexArrays(n, ids); }

using Texture = GlName<delete_textures>;
using Buffer = GlName<delete_buffers>;
using VertexArray = GlName<delete_vertex_arrays>;

// Immutable-storage texture with linear filtering; wrap mode per axis.
Texture make_texture_2d(GLenum internal_format, int w, int h, GLenum wrap_s, GLenum wrap_t);
Texture make_texture_3d(GLenum internal_format, int w, int h, int d, GLenum wrap);
// w x h x layers, linear within a layer, clamped to the edge.
Texture make_texture_2d_array(GLenum internal_format, int w, int h, int layers);
Buffer make_buffer(GLsizeiptr bytes, const void* data, GLenum usage);

}  // namespace cloudsvc::gl
