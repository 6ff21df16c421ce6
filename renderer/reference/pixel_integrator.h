// Radiance of one pixel's ray in the reference: clouds, sky or ground, aerial perspective
// (the per-pixel part of reference_renderer.h's description).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "renderer/reference/atmosphere_tables.h"
#include "renderer/reference/cloud_field.h"
#include "renderer/reference/reference_atmosphere.h"
#include "renderer/reference/reference_renderer.h"

namespace cloudsvc::reference {

struct PixelRadiance {
  glm::dvec3 radiance{0.0};  // W m^-2 sr^-1 nm^-1 at 680/550/440 nm
  double opacity = 0.0;      // 1 - cloud transmittance
};

class PixelIntegrator {
 public:
  PixelIntegrator(const CloudField& field, const AtmosphereTables& tables, const ReferenceSettings& settings);

  // dir: unit view direction, local frame. evals counts cloud density evaluations.
  PixelRadiance shade(const glm::dvec3& dir, std::uint64_t& evals) const;

 private:
  struct CloudMarch {
    glm::dvec3 radiance{0.0};   // in-scattered by clouds, not yet attenuated by the air
    double transmittance = 1.0;
    double weighted_depth = 0.0;  // sum of t * T * (1 - e^{-sigma dt}), m
  };
  CloudMarch march_clouds(const glm::dvec3& dir, double t_limit, std::uint64_t& evals) const;
  glm::dvec3 cloud_inscatter(int li, const glm::dvec3& p, double alt, double coverage, const glm::dvec3& dir,
                             std::uint64_t& evals) const;
  glm::dvec3 ground_radiance(const glm::dvec3& dir, double t_ground, std::uint64_t& evals) const;
  glm::dvec3 sky_radiance(const glm::dvec3& dir) const;
  atmo::RayInscatter air_along_ray(const glm::dvec3& dir, double t_end, bool skip_above_top) const;
  glm::dvec3 sun_transmittance(double alt, double mu) const;

  const CloudField& field_;
  const ReferenceScene& scene_;
  const AtmosphereTables& tables_;
  const ReferenceSettings& settings_;
  glm::dvec3 e_sun_;
  glm::dvec3 ground_albedo_;
  double camera_atmo_radius_;
  double tau_stop_;  // light-march cut-off depth
};

}  // namespace cloudsvc::reference
