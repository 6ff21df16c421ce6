// The dome rings of cumulus layers on the GPU (weather::dome_ring_texel,
// weather/cumulus_domes.h): a 2-D texture array, one slice per (layer slot, ring), RG32F:
// R the unit-aspect dome top of the ring's own levels (m), G the fraction the finer levels
// cover; filled by shaders/placement_rings.comp one ring at a time. The acceptance of each cloud reads the weather map at the cloud's
// centre, so the map's textures (CloudFieldTextures::bind) must be bound when a ring is
// filled. Needs a current GL 4.5 context.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "renderer/gl/gl_objects.h"
#include "renderer/gl/shader_program.h"
#include "weather/cloud_placement.h"
#include "weather/cumulus_domes.h"
#include "weather/placement_rings.h"

namespace cloudsvc {

inline constexpr int kPlacementMaxLevels = 8;  // = PLACEMENT_MAX_LEVELS (cloud_placement.glsl)

// std430 image of PlacementFrame (shaders/cloud_placement.glsl).
struct PlacementFrameGpu {
  float centre[3];
  float shell_radius_m;
  std::int32_t levels;
  float smallest_cell_m;
  float rho_min, rho_max;
  std::int32_t centre_cell[kPlacementMaxLevels][4];
  float centre_offset[kPlacementMaxLevels][4];
  float acceptance[kPlacementMaxLevels];  // where one coverage holds for the frame (tests)
  std::uint32_t level_seed[kPlacementMaxLevels];
};
static_assert(sizeof(PlacementFrameGpu) == 352, "std430 layout of PlacementFrame");

// The frame of placement cp around the centre C (field frame, m): C's cube and offset in
// it per level, computed in double so that the GPU's cube indices near C are exact. The
// acceptance values are left 0. Throws std::invalid_argument for more than
// kPlacementMaxLevels levels.
PlacementFrameGpu placement_frame_gpu(const weather::CloudPlacement& cp, const glm::dvec3& centre);

inline constexpr int kDomeWarpOctavesGpu = 5;  // = DOME_WARP_OCTAVES (dome_warp.glsl)
static_assert(kDomeWarpOctavesGpu == weather::kDomeWarpOctaves, "dome_warp.glsl's octave count");

// std430 image of DomeWarpFrame (shaders/dome_warp.glsl).
struct DomeWarpFrameGpu {
  std::int32_t cell[kDomeWarpOctavesGpu][4];
  float offset[kDomeWarpOctavesGpu][4];
  float amplitude[kDomeWarpOctavesGpu];
  float pad[3];
  std::uint32_t seed[kDomeWarpOctavesGpu][4];
};
static_assert(sizeof(DomeWarpFrameGpu) == 272, "std430 layout of DomeWarpFrame");

// The warp's octaves around the centre C (field frame, m): C / lambda as an integer cell and
// a fraction per octave, in double.
DomeWarpFrameGpu dome_warp_frame_gpu(const weather::DomeWarp& warp, const glm::dvec3& centre);

// What one ring is filled from.
struct RingInputs {
  glm::dvec3 centre{0.0};          // C: on the shell, field frame (m): the plane's tangent point
  glm::dvec2 origin{0.0};          // the ring's centre on the plane tangent at C (m)
  glm::dmat3 field_to_ecef{1.0};   // field axes -> ECEF axes
  double layer_coverage = 0.0;     // c_L, modulated by the map's coverage channel
  float map_height = 0.0f;         // weather map rows
  float map_blend = 0.0f;          // weight of the next keyframe
  glm::vec4 pole_south{0.5f}, pole_north{0.5f};
};

class PlacementRings {
 public:
  // slots: the layers that can hold rings at once.
  PlacementRings(const weather::RingLayout& layout, int slots);

  // Fills ring `ring` of slot `slot` for placement cp (at most kPlacementMaxLevels levels)
  // and its warp.
  void fill(int slot, int ring, const weather::CloudPlacement& cp, const weather::DomeWarp& warp, const RingInputs& in);

  const weather::RingLayout& layout() const { return layout_; }
  GLuint texture() const { return texture_.id(); }
  int slice(int slot, int ring) const { return slot * layout_.rings + ring; }

 private:
  weather::RingLayout layout_;
  gl::ShaderProgram program_;
  gl::Texture texture_;
  gl::Buffer job_;
  std::size_t job_bytes_ = 0;
};

}  // namespace cloudsvc
