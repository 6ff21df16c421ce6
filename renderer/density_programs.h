// A compute program that evaluates the cloud density (shaders/cloud_density.glsl), in the
// variants a frame may need:
// - without or with the cumulus-dome path (CLOUDSVC_CUMULUS_DOMES, weather/cumulus_domes.h).
//   A frame whose layers in reach include no dome layer runs the variant without it: on
//   llvmpipe every branch runs both sides (docs/PERFORMANCE.md), so code in the density
//   function costs every evaluation, whether a layer takes it or not.
// - with the dome sub-grid summed in a loop over the levels a point needs
//   (CLOUDSVC_DENSITY_LOOPS, shaders/cumulus_domes.glsl), where the quality's marches leave
//   llvmpipe's loop budget for it (density_loops_fit); written out otherwise.
// - without or with the noise volumes' stochastic tiling (CLOUDSVC_NOISE_TILING,
//   RendererConfig::noise_tiling).
// Each variant is compiled the first time a frame asks for it. Needs a current GL 4.5
// context.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "renderer/api/render_quality.h"
#include "renderer/gl/shader_program.h"

namespace cloudsvc {

// Whether the marches of quality q, with up to kDomeLevels loop iterations added to every
// density evaluation, stay well inside the 65535 loop iterations llvmpipe allows one
// shader invocation (FrameStats::loop_capped_invocations): the primary steps times the
// evaluations each makes (itself, its light steps and its marched column's steps) times
// the iterations per evaluation, with a factor 4 for the long-step probes, re-marched
// spans and the per-layer minimum of steps. True for every preset but ultra (192 primary
// steps of 12 light and 8 column steps each); false for marches of a few thousand light
// samples per ray (the accuracy tests' fine march).
bool density_loops_fit(const RenderQuality& q);

// The column steps quality q marches from each lit sample (RenderQuality::column_steps
// where the columns do not come from the column volume: without it, or without the ground
// shadow map it is built with), 0 where the volume holds them or there are none.
inline int marched_column_steps(const RenderQuality& q) {
  return q.column_volume && q.ground_shadow_map ? 0 : q.column_steps;
}

class DensityPrograms {
 public:
  // file: the compute shader; defines: those of every variant.
  explicit DensityPrograms(std::string file, std::vector<std::string> defines = {});
  // Binds the variant with or without the dome path (with loops where `loops`), with or
  // without the noise tiling (compiled on first use).
  void use(bool domes, bool loops, bool tiling) const;

 private:
  std::string file_;
  std::vector<std::string> defines_;
  // [0]: no domes, [1]: domes written out, [2]: domes with loops (the loops only matter
  // to the dome path: without it the variants are the same program); + 3 with the tiling
  mutable std::optional<gl::ShaderProgram> variant_[6];
};

}  // namespace cloudsvc
