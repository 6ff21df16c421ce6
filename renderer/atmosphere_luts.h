// Atmosphere look-up tables (Hillaire 2020). The transmittance, multiple-scattering and
// sky-irradiance LUTs depend only on the (fixed) atmosphere and are computed once; the
// sky-view LUT and the aerial-perspective volume depend on the camera and the sun and are
// recomputed per frame (DESIGN.md §4). Needs a current GL 4.5 context.
#pragma once

#include "renderer/gl/gl_objects.h"
#include "renderer/gl/shader_program.h"

namespace cloudsvc {

class AtmosphereLuts {
 public:
  static constexpr int kTransmittanceW = 256, kTransmittanceH = 64;
  static constexpr int kMultiscatterSize = 32;
  static constexpr int kIrradianceSize = 32;
  static constexpr int kSkyViewW = 192, kSkyViewH = 108;
  static constexpr int kApSize = 32;  // 32 x 32 directions x 32 depth slices

  AtmosphereLuts();  // compiles the LUT programs and computes the static LUTs

  // Recomputes the camera-dependent LUTs; the frame uniform buffer must be bound at 0.
  void update_view_dependent();

  // Binds the LUTs to the texture units the scene shader expects (0, 1, 2, 6, 7, 8).
  void bind_for_scene() const;

 private:
  gl::ShaderProgram sky_view_prog_, ap_prog_;
  gl::Texture transmittance_, multiscatter_, irradiance_, sky_view_, ap_inscatter_, ap_transmittance_;
};

// Dispatches a compute program over w x h (x d) invocations in 8x8 groups.
void dispatch_2d(int w, int h, int d = 1);

}  // namespace cloudsvc
