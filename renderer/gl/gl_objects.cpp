#include "renderer/gl/gl_objects.h"

namespace cloudsvc::gl {

Texture make_texture_2d(GLenum internal_format, int w, int h, GLenum wrap_s, GLenum wrap_t) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  glTextureStorage2D(id, 1, internal_format, w, h);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap_s));
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap_t));
  return Texture(id);
}

Texture make_texture_3d(GLenum internal_format, int w, int h, int d, GLenum wrap) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_3D, 1, &id);
  glTextureStorage3D(id, 1, internal_format, w, h, d);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
  glTextureParameteri(id, GL_TEXTURE_WRAP_R, static_cast<GLint>(wrap));
  return Texture(id);
}

Texture make_texture_2d_array(GLenum internal_format, int w, int h, int layers) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
  glTextureStorage3D(id, 1, internal_format, w, h, layers);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return Texture(id);
}

Buffer make_buffer(GLsizeiptr bytes, const void* data, GLenum usage) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  glNamedBufferData(id, bytes, data, usage);
  return Buffer(id);
}

}  // namespace cloudsvc::gl
