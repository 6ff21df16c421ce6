#include "service/window_presenter.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include <stdexcept>

#include "common/tone_map.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gpu_interface.h"

namespace cloudsvc {

struct WindowPresenter::Impl {
  GLFWwindow* window = nullptr;
  gl::ShaderProgram present;
  gl::Texture shown;
  int tex_w = 0, tex_h = 0;
  GLuint vao = 0;
  bool has_frame = false;

  void draw() {
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window, &fw, &fh);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fw, fh);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    if (has_frame) {
      present.use();
      glBindTextureUnit(gpu::tex::PRESENT_FRAME, shown.id());
      glBindVertexArray(vao);
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glfwSwapBuffers(window);
  }
};

WindowPresenter::WindowPresenter(int width, int height, const std::string& title) : impl_(std::make_unique<Impl>()) {
  if (!glfwInit()) {
    throw std::runtime_error("--window: GLFW cannot initialise (no X display? set DISPLAY or run under xvfb-run -a)");
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  impl_->window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!impl_->window) {
    glfwTerminate();
    throw std::runtime_error("--window: cannot create a 4.5 core OpenGL window");
  }
  glfwMakeContextCurrent(impl_->window);
  glfwSwapInterval(0);
  impl_->present = gl::ShaderProgram::graphics("present.vert", "present.frag");
  glCreateVertexArrays(1, &impl_->vao);
}

WindowPresenter::~WindowPresenter() {
  if (impl_->vao) glDeleteVertexArrays(1, &impl_->vao);
  impl_->shown.reset();
  impl_->present = gl::ShaderProgram();
  glfwDestroyWindow(impl_->window);
  glfwTerminate();
}

void WindowPresenter::present(const FrameImage& img, double exposure_ev) {
  if (img.width != impl_->tex_w || img.height != impl_->tex_h) {
    impl_->shown = gl::make_texture_2d(GL_RGBA8, img.width, img.height, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
    impl_->tex_w = img.width;
    impl_->tex_h = img.height;
  }
  const std::vector<std::uint8_t> px = tone_map_srgb8(img.rgba, 4, exposure_ev);  // FrameImage: RGBA
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(impl_->shown.id(), 0, 0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  impl_->has_frame = true;
  impl_->draw();
  glfwPollEvents();
}

void WindowPresenter::poll() {
  impl_->draw();
  glfwPollEvents();
}

void WindowPresenter::set_title(const std::string& title) { glfwSetWindowTitle(impl_->window, title.c_str()); }
bool WindowPresenter::close_requested() const { return glfwWindowShouldClose(impl_->window); }
GLFWwindow* WindowPresenter::window() const { return impl_->window; }

}  // namespace cloudsvc
