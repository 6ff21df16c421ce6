#include "renderer/gl/shader_program.h"

#include "renderer/gpu_interface.h"

#include <set>
#include <sstream>
#include <stdexcept>

namespace cloudsvc {
std::string_view shader_source(const std::string& name);  // generated embedded_shaders.cpp
}

namespace cloudsvc::gl {

std::string_view embedded_shader(const std::string& name) { return cloudsvc::shader_source(name); }

namespace {

void expand(const std::string& name, std::set<std::string>& seen, std::ostringstream& out) {
  if (!seen.insert(name).second) return;
  std::istringstream in{std::string(embedded_shader(name))};
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const auto pos = line.find("#include");
    if (pos != std::string::npos && line.find_first_not_of(" \t") == pos) {
      const auto a = line.find('"'), b = line.rfind('"');
      if (a == std::string::npos || b <= a) throw std::runtime_error(name + ": malformed #include");
      expand(line.substr(a + 1, b - a - 1), seen, out);
      continue;
    }
    out << line << '\n';
  }
}

GLuint compile(GLenum stage, const std::string& source, const std::string& label) {
  GLuint s = glCreateShader(stage);
  const char* src = source.c_str();
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
    glGetShaderInfoLog(s, len, nullptr, log.data());
    glDeleteShader(s);
    throw std::runtime_error("shader " + label + " failed to compile:\n" + log);
  }
  return s;
}

GLuint link(const std::vector<GLuint>& shaders, const std::string& label) {
  GLuint p = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(p, s);
  glLinkProgram(p);
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(p, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
    glGetProgramInfoLog(p, len, nullptr, log.data());
    glDeleteProgram(p);
    throw std::runtime_error("program " + label + " failed to link:\n" + log);
  }
  return p;
}

}  // namespace

std::string preprocess_shader(const std::string& name, const std::vector<std::string>& defines) {
  std::set<std::string> seen;
  std::ostringstream body;
  expand(name, seen, body);
  std::string text = body.str();
  // Insert defines after the #version line (which must be the first line).
  const auto eol = text.find('\n');
  std::string header = text.substr(0, eol + 1);
  if (header.rfind("#version", 0) != 0) throw std::runtime_error(name + ": first line must be #version");
  header += gpu::glsl_interface_preamble();
  for (const auto& d : defines) header += "#define " + d + "\n";
  header += "#line 2\n";
  return header + text.substr(eol + 1);
}

ShaderProgram ShaderProgram::compute(const std::string& file, const std::vector<std::string>& defines) {
  ShaderProgram p;
  p.id_ = link({compile(GL_COMPUTE_SHADER, preprocess_shader(file, defines), file)}, file);
  return p;
}

ShaderProgram ShaderProgram::graphics(const std::string& vert, const std::string& frag) {
  ShaderProgram p;
  p.id_ = link({compile(GL_VERTEX_SHADER, preprocess_shader(vert), vert),
                compile(GL_FRAGMENT_SHADER, preprocess_shader(frag), frag)},
               vert + "+" + frag);
  return p;
}

ShaderProgram::~ShaderProgram() {
  if (id_) glDeleteProgram(id_);
}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& o) noexcept {
  if (this != &o) {
    if (id_) glDeleteProgram(id_);
    id_ = o.id_;
    o.id_ = 0;
  }
  return *this;
}

}  // namespace cloudsvc::gl
