#include "renderer/dome_layer_gpu.h"

#include <cmath>
#include <cstring>

#include <glm/glm.hpp>

namespace cloudsvc {

DomeLayerGpu dome_layer_gpu(const weather::DomeRings& rings, const weather::RingLayout& layout,
                            const weather::CloudPlacement& cp, const weather::DomeSubgrid& subgrid, int first_slice,
                            const glm::dvec3& camera_field) {
  DomeLayerGpu d{};
  for (int i = 0; i < 3; ++i) {
    d.plane_e[i] = static_cast<float>(rings.plane.e[i]);
    d.plane_n[i] = static_cast<float>(rings.plane.n[i]);
    d.plane_c[i] = static_cast<float>(rings.plane.c[i]);
  }
  d.plane_c[3] = static_cast<float>(cp.shell_radius_m());
  for (int k = 0; k < layout.rings; ++k) {
    d.ring[k][0] = static_cast<float>(rings.origin[k].x);
    d.ring[k][1] = static_cast<float>(rings.origin[k].y);
    d.ring[k][2] = static_cast<float>(weather::ring_texel_m(layout, k));
    d.ring[k][3] = static_cast<float>(weather::ring_first_level(layout, cp.params(), k));
  }
  d.info[0] = layout.rings;
  d.info[1] = layout.size;
  d.info[2] = first_slice;
  d.info[3] = cp.params().levels;
  d.params[0] = static_cast<float>(weather::dome_ring_floor_m(layout, layout.rings - 1));
  d.params[1] = static_cast<float>(weather::kDomeSubgridMeanRadius_m);
  d.params[2] = static_cast<float>(cp.max_coverage());
  d.shape[0] = static_cast<float>(weather::kDomeTopScale_m);
  d.shape[1] = static_cast<float>(weather::kDomeCauliflower_m);
  d.shape[2] = static_cast<float>(weather::kDomeEdge_m);
  d.shape[3] = static_cast<float>(weather::kDomeBaseRamp_m);
  for (int i = 0; i < 3; ++i) d.camera_q[i] = static_cast<float>(camera_field[i] - rings.anchor[i]);
  for (int i = 0; i < kDomeSubgridOctavesGpu; ++i) {
    const weather::DomeSubgrid::Octave& oc = subgrid.octave(i);
    // glm is column-major: row r of the rotation is (m[0][r], m[1][r], m[2][r])
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) d.oct_rot[3 * i + r][c] = static_cast<float>(oc.rotation[c][r]);
    d.oct_rot[3 * i][3] = static_cast<float>(oc.weight);
    const glm::dvec3 u = oc.rotation * rings.anchor / oc.wavelength_m, cell = glm::floor(u);
    for (int a = 0; a < 3; ++a) {
      d.oct_cell[i][a] = static_cast<std::int32_t>(cell[a]);
      d.oct_frac[i][a] = static_cast<float>(u[a] - cell[a]);
    }
    std::memcpy(&d.oct_cell[i][3], &oc.seed, sizeof oc.seed);
    d.oct_frac[i][3] = static_cast<float>(1.0 / oc.wavelength_m);
  }
  for (int l = 0; l <= weather::kDomeLevels; ++l) {
    const double* q = subgrid.quantile_table(l);
    for (int j = 0; j <= weather::kDomeSubgridQuantiles; ++j)
      d.quantile[l * (weather::kDomeSubgridQuantiles + 1) + j] = static_cast<float>(q[j]);
    d.rms[l] = static_cast<float>(subgrid.rms(l));
  }
  return d;
}

}  // namespace cloudsvc
