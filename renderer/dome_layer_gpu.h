// The per-layer data shaders/cumulus_domes.glsl reads a cumulus layer's dome top with
// (DomeLayerGpu, SSBO_DOME_LAYERS): where the layer's dome rings lie (weather/dome_rings.h)
// and its sub-grid noise (weather::DomeSubgrid), relative to the rings' anchor, computed in
// double. GL-free.
#pragma once

#include <cstdint>

#include "weather/cumulus_domes.h"
#include "weather/dome_rings.h"

namespace cloudsvc {

inline constexpr int kDomeSubgridOctavesGpu = 2 * weather::kDomeLevels;  // = DOME_SUBGRID_OCTAVES

// std430 image of DomeLayerGpu (shaders/cumulus_domes.glsl).
struct DomeLayerGpu {
  float plane_e[4], plane_n[4], plane_c[4];
  float ring[weather::kDomeMaxRings][4];
  std::int32_t info[4];
  float params[4];
  float shape[4];
  float camera_q[4];
  float oct_rot[kDomeSubgridOctavesGpu * 3][4];
  std::int32_t oct_cell[kDomeSubgridOctavesGpu][4];
  float oct_frac[kDomeSubgridOctavesGpu][4];
  float quantile[(weather::kDomeLevels + 1) * (weather::kDomeSubgridQuantiles + 1)];
  float rms[weather::kDomeLevels + 1];
  float pad[2];
};
static_assert(sizeof(DomeLayerGpu) == 2144, "std430 layout of DomeLayerGpu");

// The data of a layer whose rings `rings` (of `layout`, slices first_slice..) hold placement
// cp, with sub-grid `subgrid`, for a camera at camera_field (field frame, m; the point the
// GPU's local frame origin maps to).
DomeLayerGpu dome_layer_gpu(const weather::DomeRings& rings, const weather::RingLayout& layout,
                            const weather::CloudPlacement& cp, const weather::DomeSubgrid& subgrid, int first_slice,
                            const glm::dvec3& camera_field = glm::dvec3(0.0));

}  // namespace cloudsvc
