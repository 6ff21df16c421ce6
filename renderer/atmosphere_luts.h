// Atmosphere look-up tables (Hillaire 2020). The transmittance, multiple-scattering and
// sky-irradiance LUTs depend only on the atmosphere, i.e. on its aerosol's amount
// (FrameContext::aerosol_scale, the weather's visibility): computed at the first frame and
// again when that changes. The sky-view LUT and the aerial-perspective volume depend on the
// camera and the sun as well and are recomputed when those change. Needs a current GL 4.5
// context.
#pragma once

#include "renderer/gl/gl_objects.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gpu_interface.h"
#include "renderer/frame_buffers.h"
#include "renderer/frame_context.h"

#include <cstddef>
#include <optional>

namespace cloudsvc {

class AtmosphereLuts {
 public:
  static constexpr int kTransmittanceW = 256, kTransmittanceH = 64;
  // Psi_ms and E_sky: 64 sun zenith cosines (denser at the horizon, sun_lut_mu in
  // shaders/atmosphere_model.glsl) x 32 altitudes, stored as logs.
  static constexpr int kSunLutMuNodes = 64, kSunLutAltNodes = 32;
  static constexpr int kSkyViewW = 192, kSkyViewH = 108;
  static constexpr int kApSize = 32;  // 32 x 32 directions x 32 depth slices

  AtmosphereLuts();  // compiles the LUT programs; the first frame's recompute fills the LUTs

  // GPU memory of all the LUTs (RGBA32F texels).
  static constexpr std::size_t gpu_bytes() {
    return 16u * (kTransmittanceW * kTransmittanceH + 2 * kSunLutMuNodes * kSunLutAltNodes + kSkyViewW * kSkyViewH + 2 * kApSize * kApSize * kApSize);
  }

  // Which LUTs recompute recomputes.
  struct ViewLutUpdate {
    bool atmosphere = false;          // transmittance, multiple scattering, sky irradiance
    bool sky_view = false;            // sky-view LUT
    bool aerial_perspective = false;  // aerial-perspective volume
  };

  // Decides which camera-dependent LUTs the frame needs recomputed and sets the
  // aerial-perspective volume's frustum (frame.ap) it is built or kept for. The sky-view LUT is parameterised relative to the local vertical and the
  // sun's azimuth (Hillaire 2020 §5.3), so it depends only on the camera altitude (kept
  // within 1 m) and the sun's zenith angle (within 1e-4 rad, at least ~1.4 s of sun motion;
  // longer near solar noon, when the elevation hardly changes): turning the camera or
  // flying level keeps it. The aerial-perspective volume is made of froxels of a frustum
  // kApMargin wider than the camera's (per axis, in tangent): it is kept while the camera's
  // frustum stays inside it and is not much narrower (kApMargin again), and the altitude
  // (1 m), reach (1 m) and sun direction (1e-4 rad) hold. A camera turning at 3 deg/s
  // keeps it for about a second.
  // All of them where the aerosol's amount differs from the last frame's (or at the first).
  ViewLutUpdate plan_view_dependent(FrameContext& frame);
  // Recomputes what plan_view_dependent decided, from the frame uniforms packed from its
  // frame (bound here with the static LUTs it reads).
  void recompute(const ViewLutUpdate& plan, const FrameBuffers& frame);

  static constexpr double kApMargin = 0.1f;

  // Binds every LUT at its texture unit (gpu::tex: the atmosphere, sky-view and
  // aerial-perspective units) for the passes that read them.
  void bind_lookups() const;

 private:
  // The inputs the view-dependent LUTs were last computed for: for the froxels, the
  // volume's frustum, not the camera's.
  struct ViewKey {
    ApFrustum frustum;
    double camera_altitude_m = 0.0, ap_max_distance_m = 0.0;
    glm::dvec3 sun_enu{0.0};
  };
  static bool same_sky(const ViewKey& a, const ViewKey& b);
  // The volume of key a still serves the frame (camera frustum inside, inputs unchanged).
  static bool froxels_serve(const ViewKey& a, const FrameContext& frame);
  std::optional<ViewKey> last_sky_, last_froxels_;
  std::optional<double> last_aerosol_scale_;  // the static LUTs were computed for it
  gl::ShaderProgram transmittance_prog_, multiscatter_prog_, irradiance_prog_, sky_view_prog_, ap_prog_;
  gl::Texture transmittance_, multiscatter_, irradiance_, sky_view_, ap_inscatter_, ap_transmittance_;
};


}  // namespace cloudsvc
