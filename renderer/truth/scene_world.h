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

// The world of scene (the medium must outlive it; inputs are the field's).
TruthWorld make_scene_world(const reference::ReferenceScene& scene, const reference::ReferenceInputs& inputs,
                            bool honour_stratiform, const SceneMedium& medium);

// The inputs' largest values the bound uses.
struct FieldMaxima {
  double map_coverage = 1.0, map_density = 1.0;  // weather map R and B, over texels and poles
  double base_noise = 1.0;                       // largest base-noise texel, [0, 1]
  reference::Quantiles16 base_quantiles{};
};
FieldMaxima field_maxima(const reference::ReferenceInputs& inputs);

// The bound of layer L's extinction over the altitudes [a0, a1] (1/m), as described above;
// exposed for the tests.
double cloud_extinction_bound(const reference::ReferenceLayer& L, const FieldMaxima& maxima, bool honour_stratiform,
                              double a0, double a1);

}  // namespace cloudsvc::truth
