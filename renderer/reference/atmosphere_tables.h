// Converged tables of the two atmosphere quantities that are integrals over all
// directions and would be far too slow to evaluate per sample: the multiple-scattering
// transfer Psi_ms and the sky irradiance E_sky. They follow the same definitions as the
// GPU's LUT shaders (shaders/multiscatter_lut.comp, shaders/sky_irradiance_lut.comp),
// evaluated in double with product Gauss quadrature over directions, altitude-adaptive
// integration along each direction, and finer grids; they are tables of the converged
// model, not copies of the GPU LUTs (docs/REFERENCE.md gives their convergence).
//
//   Psi_ms(alt, mu_s) = L_2nd / (1 - f_ms)                       (Hillaire 2020 eq. 9-10)
//   L_2nd = 1/(4 pi) Int_sphere L'(w) dw,   f_ms = 1/(4 pi) Int_sphere L_f(w) dw  (eq. 5-8)
//   L'(w)  = Int T(0,t) sigma_s(t) T_sun(t) / (4 pi) dt
//            + T(0,t_g) T_sun(ground) max(mu_g, 0) albedo / pi      (rays that hit the ground)
//   L_f(w) = Int T(0,t) sigma_s(t) dt
//   E_sky(alt, mu_s) = Int_upper hemisphere L_sky(w) cos(theta) dw, L_sky = single +
//            multiple scattering (atmo::integrate_inscatter) to the top of the atmosphere.
// All for unit solar irradiance. mu_s: cosine of the sun zenith angle at the point.
//
// While building the tables, the sun transmittance T_sun inside these second-order
// integrals comes from a fine table of the integrated optical depth (512 x 128 nodes,
// Bruneton's parameterisation, linear in optical depth): its error (< 1e-3 relative where
// T > 1e-3, 6.5e-4 measured, tests/reference_atmosphere_test.cpp) is below the tables' own
// (direction quadrature and interpolation, ~0.4-1 %). Everything a
// pixel sees directly (sun, sky and aerial-perspective single scattering, cloud sunlight)
// uses atmo::transmittance_to_space, integrated per call.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

namespace cloudsvc::reference {

struct AtmosphereTableSettings {
  double step_m = 500.0;           // atmo::altitude_step base step of the integrations along directions
  double max_step_m = 10000.0;     // longest step along a direction (see atmo::altitude_step)
  int mu_sun_nodes = 65;           // nodes over mu_s in [-1, 1] (see MuAltitudeTable)
  int ms_zenith_nodes = 8;         // Psi_ms: Gauss-Legendre nodes in mu above and again below the horizon
  int ms_azimuth_nodes = 6;        // ... midpoint nodes over azimuth [0, pi] (mirror symmetric)
  int sky_zenith_nodes = 10;       // E_sky: Gauss-Legendre nodes in mu over [0, 1], clustered at 0
  int sky_azimuth_nodes = 10;      // ... midpoint nodes over azimuth [0, pi]
  int threads = 0;                 // worker threads, 0 = all cores (common/parallel_for.h); no effect on the values
  double aerosol_scale = 1.0;      // the air's aerosol (atmo::medium_at); render_reference sets the scene's

  bool operator<(const AtmosphereTableSettings& o) const;
};

// Positive values on a grid of mu_s x altitude, bilinear in their logarithm in between,
// clamped at the edges. The
// mu_s nodes are mu = 0.25 x + 0.75 x^3 for x uniform in [-1, 1]: 10x denser around the
// horizon (twilight, where both quantities change fastest) than near the zenith. The
// altitude nodes are a fixed list, denser near the ground (0-100 km for Psi_ms, 0-20 km
// for E_sky).
class MuAltitudeTable {
 public:
  MuAltitudeTable(int mu_nodes, std::vector<double> altitudes_m);
  const std::vector<double>& mus() const { return mus_; }
  const std::vector<double>& altitudes() const { return altitudes_; }
  void set(std::size_t i_mu, std::size_t i_alt, const glm::dvec3& value);
  glm::dvec3 lookup(double altitude_m, double mu_sun) const;

 private:
  std::vector<double> mus_;
  std::vector<double> altitudes_;
  std::vector<glm::dvec3> log_values_;  // log(max(value, 1e-300)), interpolated by lookup
};

class AtmosphereTables {
 public:
  explicit AtmosphereTables(const AtmosphereTableSettings& settings);

  // Table lookups (what the reference renderer uses).
  glm::dvec3 multiple_scattering(double altitude_m, double mu_sun) const { return psi_ms_.lookup(altitude_m, mu_sun); }
  glm::dvec3 sky_irradiance(double altitude_m, double mu_sun) const { return e_sky_.lookup(altitude_m, mu_sun); }

  // The definitions evaluated at one point, without interpolation, with the settings'
  // quadrature and step or, for convergence tests, other node counts or another
  // integration step along the directions (0 = the settings').
  glm::dvec3 multiple_scattering_at(double altitude_m, double mu_sun, int zenith_nodes = 0, int azimuth_nodes = 0,
                                    double step_m = 0.0) const;
  glm::dvec3 sky_irradiance_at(double altitude_m, double mu_sun, int zenith_nodes = 0, int azimuth_nodes = 0,
                               double step_m = 0.0) const;
  // The fine sun-transmittance table used while building (for its test).
  glm::dvec3 tabulated_transmittance(double altitude_m, double mu) const;

  const AtmosphereTableSettings& settings() const { return settings_; }

 private:
  struct FineTransmittance {
    int n_mu = 512, n_r = 128;
    std::vector<glm::dvec3> optical_depth;  // node (i_mu, i_r) at [i_r * n_mu + i_mu]
  };
  void build_fine_transmittance();

  AtmosphereTableSettings settings_;
  FineTransmittance fine_;
  MuAltitudeTable psi_ms_;
  MuAltitudeTable e_sky_;
};

// Tables for the given settings, built once per process (thread-safe).
std::shared_ptr<const AtmosphereTables> atmosphere_tables(const AtmosphereTableSettings& settings);

}  // namespace cloudsvc::reference
