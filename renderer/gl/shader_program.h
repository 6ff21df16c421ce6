// Compiles and links GLSL programs from the shaders embedded at build time
// (cmake/EmbedShaders.cmake). Supports `#include "name.glsl"` lines, resolved against
// the embedded set (each file included at most once per program).
#pragma once

#include <epoxy/gl.h>

#include <string>
#include <vector>

namespace cloudsvc::gl {

// Embedded source of a shader file by its file name (e.g. "common.glsl").
std::string_view embedded_shader(const std::string& name);

// Source text of `name` with its includes expanded and, after #version, the CPU/GPU
// interface (gpu::glsl_interface_preamble: binding points, model constants) and `defines`.
std::string preprocess_shader(const std::string& name, const std::vector<std::string>& defines = {});

class ShaderProgram {
 public:
  ShaderProgram() = default;
  // A compute program from one file. Throws std::runtime_error with the compile log.
  static ShaderProgram compute(const std::string& file, const std::vector<std::string>& defines = {});
  // A vertex + fragment program.
  static ShaderProgram graphics(const std::string& vert, const std::string& frag);
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& o) noexcept : id_(o.id_) { o.id_ = 0; }
  ShaderProgram& operator=(ShaderProgram&& o) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  GLuint id() const { return id_; }
  void use() const { glUseProgram(id_); }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

}  // namespace cloudsvc::gl
