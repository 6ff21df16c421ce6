// A rendered frame and its statistics. Plain data shared by the GPU renderer, the CPU
// reference and the service's outputs (no GL).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cloudsvc {

// A pixel counts as cloud where its cloud opacity (1 - cloud transmittance, the alpha of a
// FrameImage) exceeds this: FrameStats::cloud_pixels of the GPU renderer and the CPU
// reference, and the cloud-pixel fraction of renderer/reference/image_metrics.h. The
// shaders receive it as CLOUD_PIXEL_OPACITY (renderer/gpu_interface.cpp).
inline constexpr double kCloudPixelOpacity = 0.01;

struct FrameStats {
  double render_ms = 0.0;             // GPU passes + readback, wall clock
  double sun_elevation_deg = 0.0;     // geometric elevation at the camera
  double sun_azimuth_deg = 0.0;
  std::int64_t cloud_pixels = 0;      // pixels with cloud opacity > kCloudPixelOpacity
  double density_evals_per_pixel = 0.0;
  std::int64_t nonfinite_pixels = 0;  // pixels the shader had to clamp (must be 0)
  // Shader invocations whose loops the GL driver cut short: Mesa's llvmpipe runs at most
  // 65535 loop iterations per invocation in all and then silently ends every loop
  // (shaders/frame_counters.glsl, count_if_loops_capped). Must be 0: where it is not, the
  // image is wrong (clouds missing or unlit); fewer steps per ray (RenderQuality) fit.
  std::int64_t loop_capped_invocations = 0;
  bool view_luts_recomputed = true;   // sky-view LUT or aerial-perspective volume redone this frame
  bool sky_view_recomputed = true;    // the sky-view LUT redone this frame (altitude or sun changed)
  int layers_without_cloud_in_view = 0;  // layers not marched: no cloud within reach (renderer/coverage_cull.h)
  // Layers drawn as individual cumulus domes (RendererConfig::cumulus_domes; those with
  // cloud within reach). 0: the frame ran the programs without the dome path.
  int dome_layers = 0;
  // With the Mie phase (RendererConfig::cloud_phase) and wait_for_phase_tables off: layers
  // drawn with the fit while their droplet size's Mie table is computed.
  int phase_tables_pending = 0;
  bool history_used = false;          // the previous frame's cloud buffer was reprojected
  bool shadow_map_rebuilt = false;    // the ground shadow map was rebuilt this frame
  double marched_fraction = 1.0;      // cloud pixels marched this frame / all cloud pixels
  std::int64_t gpu_memory_bytes = 0;  // textures and buffers the renderer holds
  // GPU time per pass (GL_TIME_ELAPSED) and the CPU time of the read-back, ms.
  double luts_ms = 0.0, march_ms = 0.0, resolve_ms = 0.0, composite_ms = 0.0, readback_ms = 0.0, shadow_map_ms = 0.0;
};

// A rendered frame: linear spectral radiance at 680/550/440 nm in W m^-2 sr^-1 nm^-1
// (rgb) and cloud opacity (a), rows from the top of the image.
struct FrameImage {
  int width = 0;
  int height = 0;
  std::vector<float> rgba;
  // Standard error of the mean of rgb per pixel (3 floats per pixel, same order), for
  // images that are Monte Carlo estimates (the path-traced ground truth); empty otherwise.
  std::vector<float> std_error;
  FrameStats stats;

  const float* pixel(int x, int y) const { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
};

}  // namespace cloudsvc
