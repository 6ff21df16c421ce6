// The cloud scene of a view as a TruthWorld (truth_world.h): the model's density field
// (reference::CloudField with detail erosion, every layer), the model's clear-sky
// atmosphere (reference::atmo::medium_at: Rayleigh, aerosol, ozone), the Lambertian ground
// of albedo model::kGroundAlbedo, the sun (model::kSolarIrradiance, angular radius
// model::kSunAngularRadiusDeg) and the night sky (model::kNightSkyRadiance, entering
// through the top), on the reference's shell geometry (reference_scene.h): the sphere of
// altitude 0 has the osculating radius R at the camera, the ground is at
// shell.ground_alt_m, the atmosphere ends 100 km above the sphere and every altitude
// (air and clouds) is measured from it.
//
// Majorant (1/m, per altitude band): the air's largest extinction in the band
// (atmo::max_extinction, largest channel) plus, for every cloud layer overlapping the band,
// a bound of its extinction there: each layer is cut into kCloudSubBands bands of equal
// height and bounded from the model's formula (cloud_field.h) with every input at its
// largest: the weather map's coverage and density channels at their maxima over the map
// (and the poles), the base noise at its largest texel, the height profile at its largest
// over the band for any depth fraction (0.3..1), detail erosion taken as none.
#pragma once

#include <memory>

#include "renderer/reference/cloud_field.h"
#include "renderer/reference/reference_inputs.h"
#include "renderer/reference/reference_scene.h"
#include "weather/noise_max_pyramid.h"
#include "renderer/truth/truth_world.h"

namespace cloudsvc::truth {

inline constexpr int kCloudSubBands = 16;

class SceneMedium final : public TruthMedium {
 public:
  SceneMedium(const reference::ReferenceScene& scene, const reference::CloudField& field);
  void at(const glm::dvec3& x, double altitude_m, MediumPoint& out) const override;

 private:
  const reference::ReferenceScene& scene_;
  const reference::CloudField& field_;
  glm::dvec3 centre_to_camera_;  // (0, 0, R + h): centred frame -> local frame offset, m
};

// The inputs' largest values the bound uses.
struct FieldMaxima {
  double map_coverage = 1.0, map_density = 1.0;  // weather map R and B, over texels and poles
  double base_noise = 1.0;                       // largest tiled base-noise value, [0, 1]
  reference::Quantiles16 base_quantiles{};
};
FieldMaxima field_maxima(const reference::ReferenceInputs& inputs);

// The local refinement of the cloud majorant (TruthWorld::local): over a stretch of ray,
// the same formula with the weather map's coverage and density at their largest over the
// texels around the stretch (the rows next to a pole and the pole's value near a pole)
// and the base noise at its largest over the texels a trilinear sample anywhere on the
// stretch can read (NoiseMaxPyramid; the stretch's noise-space bounding box, widened by
// |k - 1| (band height + altitude x stretch / R + 1 m) for the vertical noise scale k;
// through the noise's stochastic tiling where the field has it, weather::tiled_max_over).
class SceneLocalMajorant final : public LocalCloudMajorant {
 public:
  SceneLocalMajorant(const reference::ReferenceScene& scene, const reference::ReferenceInputs& inputs,
                     bool honour_stratiform, const std::vector<double>& band_edges, bool noise_tiling = false);
  double cloud_bound(int band, const glm::dvec3& a, const glm::dvec3& b) const override;
  // Largest R and B of the weather map that a bilinear sample on the segment (centred
  // frame) can read.
  glm::dvec2 map_maxima(const glm::dvec3& a, const glm::dvec3& b) const;

 private:
  const reference::ReferenceScene& scene_;
  const reference::ReferenceInputs& inputs_;
  std::vector<double> edges_;
  std::vector<std::vector<double>> profile_;  // [band][layer]: height-profile bound
  std::vector<std::vector<double>> anvil_;    // [band][layer]: largest anvil weight (CloudField::anvil_weight_max)
  weather::NoiseMaxPyramid base_;
  bool noise_tiling_ = false;
  glm::dvec2 polar_[2];  // largest R, B of the 4 rows next to the south / north pole and the pole
};

// The world of scene (medium and local must outlive it; inputs are the field's); local
// may be nullptr (band majorants only).
TruthWorld make_scene_world(const reference::ReferenceScene& scene, const reference::ReferenceInputs& inputs,
                            bool honour_stratiform, const SceneMedium& medium,
                            const SceneLocalMajorant* local = nullptr);

// The band edges make_scene_world uses (for SceneLocalMajorant).
std::vector<double> scene_band_edges(const reference::ReferenceScene& scene);

// The bound of layer L's extinction over the altitudes [a0, a1] (1/m), as described above;
// exposed for the tests.
double cloud_extinction_bound(const reference::ReferenceLayer& L, const FieldMaxima& maxima, bool honour_stratiform,
                              double a0, double a1);

}  // namespace cloudsvc::truth
