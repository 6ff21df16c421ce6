// Atmosphere look-up tables (Hillaire 2020). The transmittance, multiple-scattering and
// sky-irradiance LUTs depend only on the (fixed) atmosphere and are computed once; the
// sky-view LUT and the aerial-perspective volume depend on the camera and the sun and are
// recomputed per frame (DESIGN.md §4). Needs a current GL 4.5 context.
#pragma once

#include "renderer/gl/gl_objects.h"
#include "renderer/gl/shader_program.h"
#include "renderer/frame_uniforms.h"

#include <cstddef>
#include <optional>

namespace cloudsvc {

class AtmosphereLuts {
 public:
  static constexpr int kTransmittanceW = 256, kTransmittanceH = 64;
  static constexpr int kMultiscatterSize = 32;
  static constexpr int kIrradianceSize = 32;
  static constexpr int kSkyViewW = 192, kSkyViewH = 108;
  static constexpr int kApSize = 32;  // 32 x 32 directions x 32 depth slices

  AtmosphereLuts();  // compiles the LUT programs and computes the static LUTs

  // GPU memory of all the LUTs (RGBA32F texels).
  static constexpr std::size_t gpu_bytes() {
    return 16u * (kTransmittanceW * kTransmittanceH + kMultiscatterSize * kMultiscatterSize +
                  kIrradianceSize * kIrradianceSize + kSkyViewW * kSkyViewH + 2 * kApSize * kApSize * kApSize);
  }

  // Recomputes the camera-dependent LUTs (the frame uniform buffer must be bound at 0)
  // unless their inputs are unchanged since the last call: camera altitude within 1 m,
  // sun direction within 1e-4 rad (0.006 deg, ~1.4 s of sun motion), camera axes, field
  // of view and aerial-perspective reach unchanged. Returns true when it recomputed.
  bool update_view_dependent(const FrameUniforms& u);

  // Binds the LUTs to the texture units the scene shader expects (0, 1, 2, 6, 7, 8).
  void bind_for_scene() const;

 private:
  // The inputs the view-dependent LUTs were last computed for.
  struct ViewKey {
    glm::vec4 camera_forward, camera_right, camera_up, view, planet, sun_dir, ap_params;
  };
  static bool same_view(const ViewKey& a, const ViewKey& b);
  std::optional<ViewKey> last_view_;
  gl::ShaderProgram sky_view_prog_, ap_prog_;
  gl::Texture transmittance_, multiscatter_, irradiance_, sky_view_, ap_inscatter_, ap_transmittance_;
};

// Dispatches a compute program over w x h (x d) invocations in 8x8 groups.
void dispatch_2d(int w, int h, int d = 1);

}  // namespace cloudsvc
