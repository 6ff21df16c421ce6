// What the path tracer of the ground truth (renderer/truth/path_tracer.h) traces: a
// spherically layered world lit by a collimated sun. Plain data plus the medium's
// interface; the cloud scene fills it in renderer/truth/scene_world.h, the tests with
// media of known answers.
//
// Frame and units: "centred" Cartesian axes, origin at the centre of the sphere of
// altitude 0 (radius radius_m), axes parallel to the camera's East-North-Up axes (the
// reference's local frame shifted by (0, 0, R + h)); metres, 1/m, radiances in the units
// of sun_irradiance (W m^-2 nm^-1) per sr.
//
// Geometry: a Lambertian ground sphere at altitude ground_alt_m, vacuum above top_alt_m,
// and in between a medium whose extinction every channel bounds by a majorant that is
// constant between consecutive altitudes of band_edges (spheres concentric with the
// ground). The majorant is what delta and ratio tracking sample tentative collisions
// from (Novak et al. 2018, "Monte Carlo methods for volumetric light transport
// simulation", CGF 37(2), §4); a point whose extinction exceeds it is counted as a
// majorant violation (a bias; the tests assert there are none).
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/model/mie_phase_table.h"
#include "renderer/model/phase_function.h"
#include "weather/cloud_layer.h"

namespace cloudsvc::truth {

inline constexpr int kMaxCloudComponents = weather::kMaxCloudLayers;

// The medium at one point: its scattering components and absorption, 1/m per channel
// (680/550/440 nm). Cloud droplets scatter conservatively (single-scattering albedo 1, as
// in the model), one component per cloud layer (each its own phase function).
struct MediumPoint {
  glm::dvec3 rayleigh{0.0};    // Rayleigh scattering (phase 3/(16 pi)(1 + nu^2))
  double aerosol = 0.0;        // aerosol scattering (Cornette-Shanks phase, TruthWorld::aerosol_g)
  glm::dvec3 absorption{0.0};  // aerosol absorption + ozone
  std::array<double, kMaxCloudComponents> cloud{};  // droplet extinction = scattering, per layer

  double cloud_total() const {
    double s = 0.0;
    for (double c : cloud) s += c;
    return s;
  }
  glm::dvec3 scattering() const { return rayleigh + glm::dvec3(aerosol + cloud_total()); }
  glm::dvec3 extinction() const { return scattering() + absorption; }
};

// The medium's extinction field. Implementations must be safe to call concurrently.
class TruthMedium {
 public:
  virtual ~TruthMedium() = default;
  // x: centred frame (m); altitude_m = |x| - radius_m, passed because every caller has it.
  virtual void at(const glm::dvec3& x, double altitude_m, MediumPoint& out) const = 0;
};

// A tighter, local bound of the cloud part of a band's majorant over a stretch of ray
// (optional): for the straight segment a -> b (centred frame) inside band `band`, a bound
// of the cloud extinction at every point of the segment, 1/m. Must be safe to call
// concurrently.
class LocalCloudMajorant {
 public:
  virtual ~LocalCloudMajorant() = default;
  virtual double cloud_bound(int band, const glm::dvec3& a, const glm::dvec3& b) const = 0;
};

struct TruthWorld {
  double radius_m = 6.371e6;      // sphere of altitude 0
  double ground_alt_m = 0.0;      // Lambertian ground sphere
  double top_alt_m = 100.0e3;     // nothing above
  // Majorant bands: band i spans altitudes [band_edges[i], band_edges[i + 1]];
  // band_edges.front() = ground_alt_m, band_edges.back() = top_alt_m.
  std::vector<double> band_edges;
  std::vector<double> band_majorant;      // 1/m, >= every channel's extinction in the band
  std::vector<double> band_air_majorant;  // the part of band_majorant that bounds the air (>= 0)
  // Optional local refinement of the rest of band_majorant (the clouds): bands with
  // band_local[i] != 0 are walked in stretches of at most local_stretch_m, each with the
  // majorant air + min(band's cloud part, local->cloud_bound(...)).
  const LocalCloudMajorant* local = nullptr;
  std::vector<char> band_local;
  double local_stretch_m = 250.0;

  glm::dvec3 sun{0.0, 0.0, 1.0};        // unit, towards the sun (the same everywhere)
  glm::dvec3 sun_irradiance{0.0};       // collimated, perpendicular to the beam; 0 = no sun
  double sun_angular_radius_rad = 0.0;  // the disk seen by unscattered camera rays
  glm::dvec3 ground_albedo{0.0};
  glm::dvec3 sky_radiance{0.0};  // isotropic radiance entering through the top (night sky)

  double aerosol_g = 0.8;                                    // Cornette-Shanks asymmetry
  std::array<model::JdDParams, kMaxCloudComponents> cloud_phase{};  // per cloud component
  // Per cloud component: its tabulated Mie phase function (per wavelength; sampled by its
  // grey mean, model::PhaseTable::sample_cos_grey), where the scene scatters with it;
  // null: cloud_phase above.
  std::array<const model::PhaseTable*, kMaxCloudComponents> cloud_mie{};

  const TruthMedium* medium = nullptr;
};

}  // namespace cloudsvc::truth
