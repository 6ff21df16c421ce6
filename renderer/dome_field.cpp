#include "renderer/dome_field.h"

#include <glm/geometric.hpp>

#include "renderer/gpu_interface.h"

namespace cloudsvc {

DomeField::DomeField()
    : layout_(weather::dome_ring_layout()),
      rings_(layout_, gpu::kMaxLayers),
      buffer_(gl::make_buffer(static_cast<GLsizeiptr>(sizeof(DomeLayerGpu) * gpu::kMaxLayers), nullptr,
                              GL_DYNAMIC_DRAW)) {}

int DomeField::update(const FrameContext& frame, const weather::Weather& weather, std::uint64_t weather_generation,
                      const FrameUniforms& uniforms) {
  int filled = 0;
  bool changed = false;
  for (int i = 0; i < frame.layer_count; ++i) {
    const LayerFrame& lf = frame.layers[static_cast<std::size_t>(i)];
    Layer& L = layers_[static_cast<std::size_t>(i)];
    if (!lf.domes) continue;
    const std::uint32_t seed = weather::dome_placement_seed(weather, static_cast<std::size_t>(i));
    if (!L.placement || L.seed != seed || L.coverage != lf.layer.coverage) {
      if (!L.subgrid || L.seed != seed) L.subgrid = std::make_unique<weather::DomeSubgrid>(seed);  // ~0.1 s
      L.seed = seed;
      L.coverage = lf.layer.coverage;
      L.placement = std::make_unique<weather::CloudPlacement>(weather::dome_placement_params(L.coverage),
                                                              weather::kDomeShellRadius_m, seed);
      L.warp = std::make_unique<weather::DomeWarp>(seed);
      L.filled.reset();
    }
    // the point the local frame's origin maps to: the camera's direction from the shell
    // centre at its distance, in the layer's field frame
    const glm::dvec3 camera_field = lf.field_rotation * (frame.enu_to_ecef[2] * (frame.shell_radius_m + frame.camera_altitude_m));
    const weather::DomeRings where = weather::dome_rings_for(layout_, camera_field);
    const bool refill_all = !L.filled || L.filled->anchor != where.anchor || L.filled_generation != weather_generation;
    RingInputs in;
    in.centre = where.anchor;
    in.field_to_ecef = glm::transpose(lf.field_rotation);
    in.layer_coverage = lf.layer.coverage;
    in.map_height = uniforms.weather_map_height;
    in.map_blend = uniforms.weather_blend;
    in.pole_south = uniforms.weather_pole_south;
    in.pole_north = uniforms.weather_pole_north;
    for (int k = 0; k < layout_.rings; ++k) {
      if (!refill_all && L.filled->origin[k] == where.origin[k]) continue;
      in.origin = where.origin[k];
      rings_.fill(i, k, *L.placement, *L.warp, in);
      ++filled;
    }
    L.filled = where;
    L.filled_generation = weather_generation;
    gpu_[static_cast<std::size_t>(i)] =
        dome_layer_gpu(where, layout_, *L.placement, *L.subgrid, rings_.slice(i, 0), camera_field);
    changed = true;
  }
  if (filled > 0) glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  if (changed) glNamedBufferSubData(buffer_.id(), 0, static_cast<GLsizeiptr>(sizeof gpu_), gpu_.data());
  return filled;
}

void DomeField::bind() const {
  glBindTextureUnit(gpu::tex::DOME_RINGS, rings_.texture());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::DOME_LAYERS, buffer_.id());
}

}  // namespace cloudsvc
