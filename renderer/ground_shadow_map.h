// Ground shadow map (shaders/ground_shadow_map.glsl): per cloud layer, the layer's optical
// depth towards the sun above the ground around an anchor (the camera when it was built),
// looked up by the composite for every ground pixel. World-space, so it is stable under
// camera motion, and rebuilt only when its inputs change (issue 5):
//  - the weather (layers, map tiles, keyframe blend) changed;
//  - the sun moved by more than kSunTolDeg (the sun moves 0.25 deg per minute);
//  - the camera left the well-resolved core (kReachFraction of the warp scale K) or its
//    altitude changed K by more than half;
//  - a layer drifted with its wind by more than kReachFraction of K (between rebuilds the
//    lookup follows the drift exactly: the map is sampled at the drifted position).
// No map at night (sun more than kNightDeg below the camera's horizon) or without layers.
//
// With the same anchor and the same rebuild rules it can also hold the light volume
// (shaders/light_volume.glsl, RenderQuality::light_volume): each layer's optical depth
// towards the sun from points inside it, on the map's warped grid (kVolumeSize per side)
// times kVolumeLevels altitude levels, which the cloud march then looks up instead of
// marching towards the sun from every sample (a Beer-law shadow volume: optical depth interpolated, Beer's law applied after the
// lookup; docs/RENDERING.md). And the column volume (shaders/column_volume.glsl,
// RenderQuality::column_steps): the optical depths of each layer's cloud above and below
// points inside it along their vertical, from which the diffuse light is read (the
// independent column approximation).
#pragma once

#include <string>
#include <vector>
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "renderer/frame_uniforms.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/density_programs.h"
#include "renderer/gl/shader_program.h"
#include "renderer/cloud_pass_inputs.h"
#include "renderer/frame_context.h"
#include "renderer/shadow_map_uniforms.h"
#include "renderer/api/frame_image.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"
#include "weather/wind_drift.h"
#include "weather/cloud_layer.h"

namespace cloudsvc {

// What the map was built for.
struct ShadowMapKey {
  FrameContext anchor;         // the frame of the build (its camera is the anchor)
  std::uint64_t weather_generation = 0;
  double warp_m = 0.0;         // K
  bool light_volume = false;   // the light volume was built too
  int light_steps = 0;         // ... with this many light steps
  int column_steps = 0;        // the column volume was built with this many steps (0: not built)
};

constexpr double kSunTolDeg = 0.05;
constexpr double kReachFraction = 0.25;
constexpr double kNightDeg = -3.0;
constexpr double kMinWarpM = 8000.0;

// Warp scale K for a camera at altitude alt_m: max(kMinWarpM, 2 altitude).
double shadow_map_warp(double alt_m);

// Why the map must be rebuilt for this frame ("" = it need not be).
std::string shadow_map_stale_reason(const ShadowMapKey& key, const FrameContext& frame,
                                    std::uint64_t weather_generation);

class GroundShadowMap {
 public:
  static constexpr int kSize = 512;  // texels per side

  GroundShadowMap();

  // Rebuilds the map if stale (from `inputs`, which hold the frame uniforms packed from
  // `frame`), then uploads the lookup uniforms for this view. Returns true if it rebuilt.
  // per_pixel: no map; the composite marches the shadows of every ground pixel.
  // light_volume: also build the light volume (with the map, light_steps light steps;
  // not with per_pixel); column_steps > 0: also build the column volume with that many
  // steps per column, at least one per altitude level (not with per_pixel). column_march_steps > 0: the march marches each
  // lit sample's column in that many steps instead (every frame, needed or not). needed =
  // false (no ground in view and no march that reads a volume): nothing is built or
  // marched, the lookups are switched off for this frame, and the map kept for a later
  // frame that needs it.
  bool update(const FrameContext& frame, const CloudPassInputs& inputs, std::uint64_t weather_generation,
              int light_steps, bool per_pixel, bool light_volume, int column_steps, int column_march_steps,
              bool needed = true);

  // Binds the lookup uniforms (gpu::ubo::SHADOW_MAP), the map (gpu::tex::GROUND_SHADOW_MAP)
  // and the light and column volumes (gpu::tex::LIGHT_VOLUME, COLUMN_VOLUME) for the passes
  // that read them.
  void bind_lookups() const;

  void invalidate() { key_.reset(); }
  static constexpr int kVolumeSize = 128;   // texels per side (2K/128 under the anchor: 125 m at K = 8 km)
  static constexpr int kVolumeLevels = 16;  // altitude levels per layer
  static constexpr std::size_t kColumnVolumeBytes = static_cast<std::size_t>(gpu::kColumnVolumeTexels) *
                                                    gpu::kColumnVolumeTexels * (gpu::kColumnVolumeLevels + 1) *
                                                    gpu::kMaxLayers * 2 * sizeof(std::uint16_t);  // RG16F
  // GPU memory held: the map, the light volume and, once it has been built, the column volume.
  std::size_t gpu_bytes() const {
    return static_cast<std::size_t>(kSize) * kSize * gpu::kMaxLayers * sizeof(float) +
           static_cast<std::size_t>(kVolumeSize) * kVolumeSize * kVolumeLevels * gpu::kMaxLayers * sizeof(float) +
           (columns_ ? kColumnVolumeBytes : 0);
  }

 private:
  // Builds the map (and the light and column volumes if asked) with the lookup uniforms su
  // of the build frame.
  void build(const FrameContext& frame, const CloudPassInputs& inputs, const ShadowMapUniforms& su, bool light_volume,
             bool column_volume);

  DensityPrograms build_prog_{"ground_shadow_map.comp"};
  DensityPrograms volume_prog_{"light_volume.comp"};
  DensityPrograms column_prog_{"column_volume.comp"};
  gl::Texture map_;
  gl::Texture volume_;
  gl::Texture columns_;  // the column volume, allocated when first built
  gl::Buffer uniforms_;
  std::optional<ShadowMapKey> key_;
};

}  // namespace cloudsvc
