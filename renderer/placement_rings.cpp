#include "renderer/placement_rings.h"

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "renderer/gl/compute_dispatch.h"
#include "renderer/gpu_interface.h"

namespace cloudsvc {

namespace {

// std430 image of RingJob (shaders/placement_rings.comp); the acceptance table follows it.
struct RingJobGpu {
  PlacementFrameGpu pf;
  DomeWarpFrameGpu warp;
  float field_to_ecef[16];  // mat4, columns
  float plane_e[4], plane_n[4];
  float pole_south[4], pole_north[4];
  float origin[2];
  float texel_m;
  std::int32_t size, first_level, end_level, warp_octaves;
  float floor_m;
  std::int32_t slice;
  float layer_coverage, map_height, map_blend;
  std::int32_t table_steps;
  float pad[3];
};
static_assert(sizeof(RingJobGpu) == 816, "std430 layout of RingJob");

}  // namespace

PlacementFrameGpu placement_frame_gpu(const weather::CloudPlacement& cp, const glm::dvec3& centre) {
  if (cp.params().levels > kPlacementMaxLevels)
    throw std::invalid_argument("cloud placement: at most " + std::to_string(kPlacementMaxLevels) + " levels on the GPU");
  PlacementFrameGpu f{};
  for (int i = 0; i < 3; ++i) f.centre[i] = static_cast<float>(centre[i]);
  f.shell_radius_m = static_cast<float>(cp.shell_radius_m());
  f.levels = cp.params().levels;
  f.smallest_cell_m = static_cast<float>(cp.params().smallest_cell_m);
  f.rho_min = static_cast<float>(cp.params().rho_min);
  f.rho_max = static_cast<float>(cp.params().rho_max);
  for (int k = 0; k < f.levels; ++k) {
    const double s = cp.params().smallest_cell_m * std::ldexp(1.0, k);
    const glm::dvec3 cell = glm::floor(centre / s);
    for (int i = 0; i < 3; ++i) {
      f.centre_cell[k][i] = static_cast<std::int32_t>(cell[i]);
      f.centre_offset[k][i] = static_cast<float>(centre[i] - cell[i] * s);
    }
    f.level_seed[k] = cp.level_seed(k);
  }
  return f;
}

DomeWarpFrameGpu dome_warp_frame_gpu(const weather::DomeWarp& warp, const glm::dvec3& centre) {
  DomeWarpFrameGpu f{};
  for (int o = 0; o < kDomeWarpOctavesGpu; ++o) {
    const weather::DomeWarp::Octave& oc = warp.octave(o);
    const glm::dvec3 u = centre / oc.wavelength_m, cell = glm::floor(u);
    for (int i = 0; i < 3; ++i) {
      f.cell[o][i] = static_cast<std::int32_t>(cell[i]);
      f.offset[o][i] = static_cast<float>(u[i] - cell[i]);
      f.seed[o][i] = oc.seed[i];
    }
    f.offset[o][3] = static_cast<float>(1.0 / oc.wavelength_m);
    f.amplitude[o] = static_cast<float>(oc.amplitude_m);
  }
  return f;
}

PlacementRings::PlacementRings(const weather::RingLayout& layout, int slots)
    : layout_(layout),
      program_(gl::ShaderProgram::compute("placement_rings.comp")),
      texture_(gl::make_texture_2d_array(GL_RG32F, layout.size, layout.size, slots * layout.rings)) {}

void PlacementRings::fill(int slot, int ring, const weather::CloudPlacement& cp, const weather::DomeWarp& warp,
                          const RingInputs& in) {
  const weather::RingPlane plane = weather::ring_plane(in.centre);
  RingJobGpu job{};
  job.pf = placement_frame_gpu(cp, in.centre);
  job.warp = dome_warp_frame_gpu(warp, in.centre);
  std::memcpy(job.field_to_ecef, glm::value_ptr(glm::mat4(glm::mat3(in.field_to_ecef))), sizeof job.field_to_ecef);
  for (int i = 0; i < 3; ++i) {
    job.plane_e[i] = static_cast<float>(plane.e[i]);
    job.plane_n[i] = static_cast<float>(plane.n[i]);
  }
  std::memcpy(job.pole_south, glm::value_ptr(in.pole_south), sizeof job.pole_south);
  std::memcpy(job.pole_north, glm::value_ptr(in.pole_north), sizeof job.pole_north);
  job.origin[0] = static_cast<float>(in.origin.x);
  job.origin[1] = static_cast<float>(in.origin.y);
  job.texel_m = static_cast<float>(weather::ring_texel_m(layout_, ring));
  job.size = layout_.size;
  job.first_level = weather::ring_first_level(layout_, cp.params(), ring);
  job.end_level = cp.params().levels;
  job.warp_octaves = weather::dome_warp_octaves(weather::ring_texel_m(layout_, ring));
  job.floor_m = static_cast<float>(weather::dome_ring_floor_m(layout_, ring));
  job.slice = slice(slot, ring);
  job.layer_coverage = static_cast<float>(in.layer_coverage);
  job.map_height = in.map_height;
  job.map_blend = in.map_blend;
  job.table_steps = weather::CloudPlacement::kCoverageSteps;

  std::vector<std::uint8_t> bytes(sizeof job + cp.acceptance_table().size() * sizeof(float));
  std::memcpy(bytes.data(), &job, sizeof job);
  for (std::size_t i = 0; i < cp.acceptance_table().size(); ++i) {
    const float p = static_cast<float>(cp.acceptance_table()[i]);
    std::memcpy(bytes.data() + sizeof job + i * sizeof(float), &p, sizeof p);
  }
  if (!job_ || bytes.size() != job_bytes_) {
    job_ = gl::make_buffer(static_cast<GLsizeiptr>(bytes.size()), nullptr, GL_DYNAMIC_DRAW);
    job_bytes_ = bytes.size();
  }
  glNamedBufferSubData(job_.id(), 0, static_cast<GLsizeiptr>(bytes.size()), bytes.data());
  program_.use();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::PLACEMENT_RING_JOB, job_.id());
  glBindImageTexture(gpu::img::PLACEMENT_RINGS_OUT, texture_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RG32F);
  gl::dispatch_2d(layout_.size, layout_.size);
}

}  // namespace cloudsvc
