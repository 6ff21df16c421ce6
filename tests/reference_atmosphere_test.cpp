// The reference's atmosphere (renderer/reference/reference_atmosphere.h, atmosphere_tables.h):
// transmittance against closed forms, convergence of the integrations and tables, and
// facts about the clear sky that any correct model must show.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "renderer/model/atmosphere_constants.h"
#include "renderer/reference/atmosphere_tables.h"
#include "renderer/reference/reference_atmosphere.h"
#include "renderer/reference/reference_renderer.h"
#include "tests/make_view.h"
#include "weather/cloud_layer.h"
#include "weather/station_weather.h"

namespace cloudsvc::reference {
namespace {

constexpr double kPi = std::numbers::pi;
using atmo::kBottomRadius;

// Vertical path from altitude a to h through sigma(alt) = sigma0 e^{-alt/H}:
// tau = sigma0 H (e^{-a/H} - e^{-h/H}).
double exponential_vertical_depth(double sigma0, double H, double a, double h) {
  return sigma0 * H * (std::exp(-a / H) - std::exp(-h / H));
}

TEST(ReferenceAtmosphere, ExponentialVerticalPathMatchesClosedForm) {
  for (double H : {8000.0, 1200.0}) {
    const double sigma0 = 1.0e-5;
    const auto profile = [&](double alt) { return glm::dvec3(sigma0 * std::exp(-std::max(alt, 0.0) / H)); };
    double previous_error = 0.0;
    for (double step : {500.0, 250.0}) {
      const double a = 0.0, h = 100000.0;
      const double tau = atmo::integrate_optical_depth(kBottomRadius + a, 1.0, h - a, step, profile).x;
      const double exact = exponential_vertical_depth(sigma0, H, a, h);
      const double error = std::abs(tau / exact - 1.0);
      std::printf("H = %5.0f m, step %3.0f m: tau %.9f exact %.9f rel. error %.2e\n", H, step, tau, exact, error);
      EXPECT_LT(error, 2e-5);
      // Two-point Gauss-Legendre is fourth order: halving the step divides the error by ~16.
      if (step == 250.0 && previous_error > 1e-12) {
        EXPECT_LT(error, previous_error / 8.0);
      }
      previous_error = error;
    }
    // A path starting aloft, ending below the top: exp(-sigma0 H (e^{-a/H} - e^{-h/H})).
    const double T = std::exp(-atmo::integrate_optical_depth(kBottomRadius + 1500.0, 1.0, 6500.0, 500.0, profile).x);
    EXPECT_NEAR(T, std::exp(-exponential_vertical_depth(sigma0, H, 1500.0, 8000.0)), 2e-7);
  }
}

TEST(ReferenceAtmosphere, VerticalTransmittanceOfTheModelAtmosphere) {
  // From the ground (the model starts at 1 m) to the top: Rayleigh and Mie exponentials in
  // closed form, ozone a tent of height 1 and half-width 15 km (area 15 km).
  const double a = 1.0, top = atmo::kThickness;
  const glm::dvec3 tau = atmo::kRayleighScattering * exponential_vertical_depth(1.0, 8000.0, a, top) +
                         glm::dvec3(exponential_vertical_depth(atmo::kMieExtinction, 1200.0, a, top)) +
                         atmo::kOzoneAbsorption * 15000.0;
  const glm::dvec3 T = atmo::transmittance_to_space(0.0, 1.0, 500.0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(T[c] / std::exp(-tau[c]), 1.0, 1e-5) << c;
  std::printf("vertical transmittance 680/550/440 nm: %.5f %.5f %.5f\n", T.r, T.g, T.b);
}

TEST(ReferenceAtmosphere, SlantAndGrazingPathsConvergeWithTheStep) {
  for (double mu : {0.3, 0.05, 0.0, -0.01}) {
    const double r = kBottomRadius + 1000.0;
    const double len = atmo::distance_to_top(r, mu);
    const glm::dvec3 coarse = atmo::optical_depth(r, mu, len, 500.0);
    const glm::dvec3 fine = atmo::optical_depth(r, mu, len, 20.0);
    std::printf("mu %5.2f: optical depth (550 nm) %.6f, step 500 m vs 20 m: rel. diff %.2e\n", mu, coarse.g,
                std::abs(coarse.g / fine.g - 1.0));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(coarse[c] / fine[c], 1.0, 1e-4) << mu;
  }
}

TEST(ReferenceAtmosphere, PlanetBlocksTheSunBelowTheHorizon) {
  // Horizon dip at 1 km: mu_h = -sqrt(1 - (R / (R + 1 km))^2) = -0.0177.
  EXPECT_EQ(atmo::transmittance_to_space(1000.0, -0.02, 500.0), glm::dvec3(0.0));
  EXPECT_GT(atmo::transmittance_to_space(1000.0, -0.015, 500.0).r, 0.0);
  EXPECT_TRUE(atmo::ray_hits_ground(kBottomRadius + 1000.0, -0.02));
  EXPECT_FALSE(atmo::ray_hits_ground(kBottomRadius + 1000.0, -0.015));
}

const AtmosphereTables& default_tables() {
  static const std::shared_ptr<const AtmosphereTables> t = atmosphere_tables(AtmosphereTableSettings{});
  return *t;
}

void fine_transmittance_table_matches_direct_integration() {
  const AtmosphereTables& t = default_tables();
  double worst = 0.0;
  for (double alt : {0.0, 300.0, 1234.0, 5000.0, 17000.0, 42000.0})
    for (double mu : {1.0, 0.7, 0.3, 0.1, 0.03, 0.0, -0.01, -0.05, -0.2}) {
      const glm::dvec3 direct = atmo::transmittance_to_space(alt, mu, t.settings().step_m);
      const glm::dvec3 table = t.tabulated_transmittance(alt, mu);
      for (int c = 0; c < 3; ++c) {
        if (direct[c] < 1e-3) {
          EXPECT_NEAR(table[c], direct[c], 1e-5);
          continue;
        }
        worst = std::max(worst, std::abs(table[c] / direct[c] - 1.0));
      }
    }
  std::printf("fine transmittance table: worst relative error %.2e (where T > 1e-3)\n", worst);
  EXPECT_LT(worst, 1e-3);
}

// Doubling the direction quadrature or halving the integration step along the directions
// changes Psi_ms and E_sky by less than 1 % where they matter (sun above -3 degrees), and
// the tables interpolate within 2 % between nodes.
void multiple_scattering_and_sky_irradiance_tables_are_converged() {
  const AtmosphereTables& t = default_tables();
  const AtmosphereTableSettings& s = t.settings();
  double dir_psi = 0, dir_sky = 0, step_psi = 0, step_sky = 0, interp_psi = 0, interp_sky = 0;
  const auto rel = [](const glm::dvec3& a, const glm::dvec3& b) {
    double m = 0.0;
    for (int c = 0; c < 3; ++c) m = std::max(m, std::abs(a[c] / b[c] - 1.0));
    return m;
  };
  for (double alt : {0.0, 700.0, 1800.0, 5000.0, 11000.0})
    for (double mu : {0.95, 0.55, 0.21, 0.07, 0.013, -0.03}) {
      const glm::dvec3 psi = t.multiple_scattering_at(alt, mu);
      const glm::dvec3 sky = t.sky_irradiance_at(alt, mu);
      dir_psi = std::max(dir_psi, rel(psi, t.multiple_scattering_at(alt, mu, 2 * s.ms_zenith_nodes, 2 * s.ms_azimuth_nodes)));
      dir_sky = std::max(dir_sky, rel(sky, t.sky_irradiance_at(alt, mu, 2 * s.sky_zenith_nodes, 2 * s.sky_azimuth_nodes)));
      step_psi = std::max(step_psi, rel(psi, t.multiple_scattering_at(alt, mu, 0, 0, 0.5 * s.step_m)));
      step_sky = std::max(step_sky, rel(sky, t.sky_irradiance_at(alt, mu, 0, 0, 0.5 * s.step_m)));
      interp_psi = std::max(interp_psi, rel(t.multiple_scattering(alt, mu), psi));
      interp_sky = std::max(interp_sky, rel(t.sky_irradiance(alt, mu), sky));
    }
  std::printf("Psi_ms: doubled directions %.2e, halved step %.2e, interpolation %.2e\n", dir_psi, step_psi, interp_psi);
  std::printf("E_sky:  doubled directions %.2e, halved step %.2e, interpolation %.2e\n", dir_sky, step_sky, interp_sky);
  EXPECT_LT(dir_psi, 0.01);
  EXPECT_LT(dir_sky, 0.01);
  EXPECT_LT(step_psi, 0.01);
  EXPECT_LT(step_sky, 0.01);
  EXPECT_LT(interp_psi, 0.02);
  EXPECT_LT(interp_sky, 0.02);
}

// Clear-sky facts: with the sun at the zenith the diffuse sky light on the ground is a
// modest fraction of the direct beam (measured clear-sky diffuse fractions are ~10-20 % of
// global irradiance), larger in the blue than in the red; it falls by orders of magnitude
// once the sun is 12 degrees below the horizon.
void sky_irradiance_facts() {
  const AtmosphereTables& t = default_tables();
  const glm::dvec3 sky = t.sky_irradiance(0.0, 1.0);
  const glm::dvec3 direct = atmo::transmittance_to_space(0.0, 1.0, 500.0);
  const glm::dvec3 fraction = sky / (sky + direct);
  std::printf("diffuse fraction, sun at zenith: %.3f %.3f %.3f\n", fraction.r, fraction.g, fraction.b);
  EXPECT_GT(fraction.g, 0.04);
  EXPECT_LT(fraction.g, 0.2);
  EXPECT_GT(fraction.b, fraction.g);
  EXPECT_GT(fraction.g, fraction.r);
  EXPECT_LT(t.sky_irradiance(0.0, std::sin(-12.0 * kPi / 180.0)).g, 1e-2 * sky.g);
}

ViewRequest view(double alt, double heading, double pitch, const char* time, int w, int h, double fov) {
  return test::make_view(47.45, 8.56, alt, heading, pitch, time, w, h, fov);
}

// Looking straight at the noon sun (elevation 66 deg) with a field of view smaller than the
// disk: every pixel sees E_sun / Omega_sun * T(view) plus a little aureole. The slant
// transmittance is within 0.1 % of the plane-parallel exp(-tau_vertical / mu) at 24 deg.
void sun_disk_radiance_is_solar_irradiance_over_solid_angle_times_transmittance() {
  const ViewRequest v = view(0.0, 0.0, 0.0, "2026-06-21T11:30:00Z", 4, 4, 0.1);
  weather::Weather clear;
  FrameImage probe = render_reference(v, clear);  // for the sun position
  const double el = probe.stats.sun_elevation_deg, az = probe.stats.sun_azimuth_deg;
  ViewRequest at_sun = v;
  at_sun.attitude = {az, el, 0.0};
  const FrameImage img = render_reference(at_sun, clear);
  const double mu = std::sin(el * kPi / 180.0);
  const double omega = 2.0 * kPi * (1.0 - std::cos(kSunAngularRadiusDeg * kPi / 180.0));
  const glm::dvec3 T_vertical = atmo::transmittance_to_space(0.0, 1.0, 500.0);
  for (int c = 0; c < 3; ++c) {
    const double expected = kSolarIrradiance[c] / omega * std::pow(T_vertical[c], 1.0 / mu);
    const double got = img.pixel(1, 1)[c];
    std::printf("sun disk channel %d: %.1f expected %.1f (sky adds %.2e)\n", c, got, expected, got - expected);
    EXPECT_NEAR(got / expected, 1.0, 2e-3);
  }
}

// Rayleigh scattering makes the zenith sky bluer than the sky near the horizon, where long
// paths redden it; night (sun 18 deg down) is dark but never zero (night-sky radiance).
void zenith_bluer_than_horizon_and_night_dark() {
  weather::Weather clear;
  const FrameImage up = render_reference(view(10.0, 0.0, 90.0, "2026-06-21T11:30:00Z", 3, 3, 5.0), clear);
  const FrameImage horizon = render_reference(view(10.0, 0.0, 2.0, "2026-06-21T11:30:00Z", 3, 3, 2.0), clear);
  const float* z = up.pixel(1, 1);
  const float* hz = horizon.pixel(1, 0);
  std::printf("zenith rgb %.4f %.4f %.4f, horizon rgb %.4f %.4f %.4f\n", z[0], z[1], z[2], hz[0], hz[1], hz[2]);
  EXPECT_GT(z[2] / z[0], 1.5);
  EXPECT_GT(z[2] / z[0], 1.3 * hz[2] / hz[0]);
  EXPECT_GT(z[2], 0.01);  // clear noon zenith sky at 440 nm: ~0.05-0.1 W m^-2 sr^-1 nm^-1
  EXPECT_LT(z[2], 0.3);
  const FrameImage night = render_reference(view(10.0, 0.0, 30.0, "2026-06-21T23:30:00Z", 3, 3, 5.0), clear);
  EXPECT_LT(night.stats.sun_elevation_deg, -17.0);
  EXPECT_LT(night.pixel(1, 1)[1], 1e-5 * z[1]);
  EXPECT_GE(night.pixel(1, 1)[1], static_cast<float>(kNightSkyRadiance));
  EXPECT_EQ(night.stats.nonfinite_pixels, 0);
}

// The checks that need the atmosphere tables run in two tests (ctest starts one process per
// test, and each process builds the tables once, ~3 s of CPU).
TEST(ReferenceAtmosphere, TablesAreConverged) {
  fine_transmittance_table_matches_direct_integration();
  multiple_scattering_and_sky_irradiance_tables_are_converged();
}

TEST(ReferenceAtmosphere, ClearSkyFacts) {
  sky_irradiance_facts();
  sun_disk_radiance_is_solar_irradiance_over_solid_angle_times_transmittance();
  zenith_bluer_than_horizon_and_night_dark();
}


// A visibility V sets the aerosol so that the sea-level extinction at 550 nm is
// -ln 0.05 / V (the meteorological optical range, model::atmosphere::aerosol_scale_for_visibility):
// a horizontal beam at the ground keeps 5 % over V; unset keeps the model's own haze, and
// air clearer than the molecules allow has no aerosol. Haze dims the sun and brightens the
// sky's light on the ground (its tables are built for the scale: AtmosphereTableSettings).
TEST(ReferenceAtmosphere, VisibilitySetsTheHaze) {
  namespace a = model::atmosphere;
  EXPECT_EQ(a::aerosol_scale_of(std::nullopt), 1.0);
  const double own_v = -std::log(a::kVisibilityContrast) / (a::kRayleighScattering.y + a::kMieExtinction);
  std::printf("the model's own visibility: %.1f km\n", own_v / 1000.0);
  EXPECT_NEAR(a::aerosol_scale_for_visibility(own_v), 1.0, 1e-12);
  EXPECT_NEAR(weather::kClearAirVisibility_m, own_v, 1e-3 * own_v);  // what METAR's "or more" counts as
  EXPECT_EQ(a::aerosol_scale_for_visibility(300e3), 0.0);
  EXPECT_EQ(a::aerosol_scale_for_visibility(weather::kMaxVisibility_m), 0.0);
  double last = 1e30;
  for (double V : {weather::kMinVisibility_m, 3e3, 10e3, 50e3}) {
    const double s = a::aerosol_scale_for_visibility(V);
    EXPECT_LT(s, last);
    last = s;
    EXPECT_NEAR(-std::log(a::kVisibilityContrast) / atmo::medium_at(0.0, s).extinction.y, V, 1e-9 * V);
    if (V <= 10e3) {  // the beam 2 m up rises by V^2 / 2R (8 m at 10 km) into thinner haze
      const double t = std::exp(-atmo::optical_depth(kBottomRadius + 2.0, 0.0, V, 10.0, s).y);
      std::printf("visibility %5.0f m: aerosol x %.1f, horizontal transmittance over it %.4f\n", V, s, t);
      EXPECT_NEAR(t, a::kVisibilityContrast, 0.03 * a::kVisibilityContrast);
    }
  }
  // haze of 10 km against the default, sun 40 deg up: less sun on the ground, more sky light
  const double s10 = a::aerosol_scale_for_visibility(10e3), mu = std::sin(40.0 * kPi / 180.0);
  AtmosphereTableSettings hazy;
  hazy.aerosol_scale = s10;
  const glm::dvec3 sun_clear = atmo::transmittance_to_space(0.0, mu, 50.0), sun_hazy = atmo::transmittance_to_space(0.0, mu, 50.0, s10);
  const glm::dvec3 sky_clear = atmosphere_tables({})->sky_irradiance(0.0, mu), sky_hazy = atmosphere_tables(hazy)->sky_irradiance(0.0, mu);
  std::printf("10 km haze, sun 40 deg: direct sun x %.3f, sky irradiance x %.3f (550 nm)\n", sun_hazy.y / sun_clear.y,
              sky_hazy.y / sky_clear.y);
  EXPECT_LT(sun_hazy.y, 0.85 * sun_clear.y);
  EXPECT_GT(sky_hazy.y, 1.2 * sky_clear.y);
  // and the haze is whiter than the blue sky: its sky light gains most in the red
  EXPECT_GT(sky_hazy.x / sky_clear.x, sky_hazy.z / sky_clear.z);
}

}  // namespace
}  // namespace cloudsvc::reference
