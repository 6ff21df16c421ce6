// The clear sky as the product renders it (CloudRenderer's LUT path: transmittance,
// Psi_ms and sky-view LUTs; headless EGL on llvmpipe) and as the CPU reference computes it
// (direct integration with Hillaire's Psi_ms at converged settings), against an
// independent brute-force Monte Carlo of the same atmosphere with all orders of multiple
// scattering (renderer/reference/atmosphere_monte_carlo.h), at noon and at sunset, camera at
// 500 m, five view directions. The pixel compared is the centre of a 3x3 frame (its ray is
// the camera's forward axis exactly), divided by the solar irradiance (radiance for unit
// irradiance, sr^-1). A table is printed; docs/ACCURACY.md §4 "Clear-sky atmosphere" holds
// the measured numbers and the reasoning for each tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "render_test_support.h"
#include "renderer/reference/atmosphere_monte_carlo.h"
#include "renderer/reference/reference_atmosphere.h"
#include "renderer/reference/reference_renderer.h"
#include "renderer/reference/reference_scene.h"
#include "renderer/model/scene_constants.h"

namespace cloudsvc::test {
namespace {

constexpr double kCameraAlt = 500.0;  // m above the ellipsoid = above the atmosphere's ground sphere
constexpr double kLat = 47.45, kLon = 8.56;

struct SunCase {
  const char* name;
  const char* time_utc;
  double min_el, max_el;  // expected sun elevation (deg), checked
  // tolerances |GPU / MC - 1| per direction (systematic part; see docs/ACCURACY.md)
  double tol[7];
};

struct Direction {
  const char* name;
  double azimuth_from_sun_deg, elevation_deg;
};

// The last two look at the ground 2.9 km away (aerial perspective over a Lambertian ground
// lit by the sun and the sky; the product's ground is the osculating sphere at the camera,
// the MC's the 6360 km sphere: the hit points differ by < 1 m, their sun angle by 0.03 deg).
constexpr int kDirectionCount = 7;
const Direction kDirections[kDirectionCount] = {{"zenith", 0.0, 90.0},
                                                {"45 deg, towards the sun", 0.0, 45.0},
                                                {"45 deg, away from the sun", 180.0, 45.0},
                                                {"horizon +5, towards the sun", 0.0, 5.0},
                                                {"horizon +5, away from the sun", 180.0, 5.0},
                                                {"ground -10, towards the sun", 0.0, -10.0},
                                                {"ground -10, away from the sun", 180.0, -10.0}};

struct Sample {
  glm::dvec3 gpu, ref;
  reference::mc::McEstimate mc[3];
  glm::dvec3 single_integral;  // deterministic single scattering (no Psi_ms)
};

TEST(AccuracyAtmosphereMc, ClearSkyNoonAndSunsetAgainstMonteCarlo) {
  const SunCase cases[] = {
      // measured 2026-12-02 (this test's table, docs/ACCURACY.md §4): noon within 2.9 %
      // everywhere; at sunset the product is low by up to 4.2 % at 45 deg, 5.5 % (towards) /
      // 8.0 % (away, blue) at the horizon and 8.6 / 9.6 % (blue) on the sky-lit ground:
      // Hillaire's isotropic Psi_ms underestimates multiple scattering at low sun (the CPU
      // reference, with the same approximation and no LUTs, is as low); at the zenith blue is
      // 3.2 % high. Tolerance = the 2026-12-01 run's values + ~1.5-2 points; against the
      // 2026-12-02 run the margin is 0.14 points at the noon ground (blue -2.86 %), and the
      // sunset zenith blue (+3.19 %) is above its 3 % and passes only on the 3 x s.e. term.
      {"noon", "2026-06-21T10:00:00Z", 58.0, 66.0, {0.035, 0.035, 0.035, 0.035, 0.035, 0.03, 0.03}},
      {"sunset", "2026-06-21T19:00:00Z", 2.0, 5.0, {0.03, 0.05, 0.05, 0.075, 0.10, 0.11, 0.17}},
  };
  weather::Weather clear = *weather::preset("clear");
  reference::mc::McSettings mcs;
  mcs.paths = 10000;
  const reference::mc::McAtmosphere atmosphere;
  double mc_seconds = 0.0;
  bool first_row = true;
  for (const SunCase& sc : cases) {
    const ViewRequest probe = make_view(kLat, kLon, kCameraAlt, 0.0, 0.0, sc.time_utc, 3, 3, 1.0);
    const reference::ReferenceScene ps = reference::make_reference_scene(probe, clear);
    ASSERT_GE(ps.sun_elevation_deg, sc.min_el) << sc.name;
    ASSERT_LE(ps.sun_elevation_deg, sc.max_el) << sc.name;
    std::printf("\n%s: %s, sun elevation %.2f deg, azimuth %.2f deg\n", sc.name, sc.time_utc, ps.sun_elevation_deg,
                ps.sun_azimuth_deg);
    if (first_row) {
      std::printf("%-7s %-30s %3s %12s %9s %7s %12s %8s %12s %8s %8s %8s %7s %8s\n", "sun", "direction", "ch", "MC total",
                  "+- s.e.", "rel.se", "GPU", "GPU/MC-1", "reference", "ref/MC-1", "MS/SS", "refMS/MC", "MS s.e.", "SS chk");
      first_row = false;
    }
    for (int di = 0; di < kDirectionCount; ++di) {
      const Direction& dir = kDirections[di];
      const double heading = std::fmod(ps.sun_azimuth_deg + dir.azimuth_from_sun_deg, 360.0);
      const ViewRequest v = make_view(kLat, kLon, kCameraAlt, heading, dir.elevation_deg, sc.time_utc, 3, 3, 1.0);
      const reference::ReferenceScene rs = reference::make_reference_scene(v, clear);
      const glm::dvec3 d = rs.camera.ray_at(1.5, 1.5);
      const FrameImage gpu = render_weather(clear, v);
      const FrameImage ref = reference::render_reference(v, clear);
      Sample s;
      for (int c = 0; c < 3; ++c) {
        s.gpu[c] = (gpu.pixel(1, 1)[c] - model::kNightSkyRadiance) / model::kSolarIrradiance[c];
        s.ref[c] = (ref.pixel(1, 1)[c] - reference::kNightSkyRadiance) / reference::kSolarIrradiance[c];
        reference::mc::McSettings cs = mcs;
        cs.seed = 1000 + 10 * di + c;
        s.mc[c] = reference::mc::sky_radiance(atmosphere, kCameraAlt, d, rs.sun_local, c, cs);
        mc_seconds += s.mc[c].seconds;
      }
      const double r0 = reference::atmo::radius_for_altitude(kCameraAlt);
      const auto T = [](double alt, double mu) { return reference::atmo::transmittance_to_space(alt, mu, 500.0); };
      const auto none = [](double, double) { return glm::dvec3(0.0); };
      // single scattering of the air along the ray (plus, for a ground pixel, the sunlit
      // ground seen through it: the MC's "single" part is the first vertex's NEE)
      const double t_end = reference::atmo::path_length(r0, d.z);
      const reference::atmo::RayInscatter air =
          reference::atmo::integrate_inscatter(r0, d, rs.sun_local, t_end, false, 500.0, 10000.0, T, none);
      s.single_integral = air.radiance;
      if (reference::atmo::ray_hits_ground(r0, d.z)) {
        const glm::dvec3 x = glm::dvec3(0.0, 0.0, r0) + t_end * d;
        const double mu_s = glm::dot(glm::normalize(x), rs.sun_local);
        s.single_integral += air.transmittance * reference::atmo::kGroundAlbedo / 3.14159265358979323846 *
                             std::max(mu_s, 0.0) * T(0.0, mu_s);
      }
      for (int c = 0; c < 3; ++c) {
        const auto& m = s.mc[c];
        const double gpu_err = s.gpu[c] / m.total.mean - 1.0, ref_err = s.ref[c] / m.total.mean - 1.0;
        const double ss_sigma = (m.single.mean - s.single_integral[c]) / m.single.std_error;
        // the reference's multiple scattering (its total minus the same single-scattering
        // integral) over the MC's: the Psi_ms approximation alone (sky directions only)
        const double ms_ratio = (s.ref[c] - s.single_integral[c]) / m.multiple.mean;
        std::printf("%-7s %-30s %3d %12.5e %9.2e %6.2f%% %12.5e %+7.2f%% %12.5e %+7.2f%% %8.3f %8.3f %6.1f%% %+7.2fs\n",
                    sc.name, dir.name, c, m.total.mean, m.total.std_error, 100.0 * m.total.std_error / m.total.mean,
                    s.gpu[c], 100.0 * gpu_err, s.ref[c], 100.0 * ref_err, m.multiple.mean / m.single.mean,
                    d.z > 0.0 ? ms_ratio : 0.0, 100.0 * m.multiple.std_error / m.multiple.mean, ss_sigma);
        // The MC's own single-scattering part must agree with the deterministic integral
        // (a check of the MC at every compared direction).
        EXPECT_LT(std::abs(ss_sigma), 4.5) << sc.name << " " << dir.name << " ch " << c;
        // The tolerance is a systematic bound; the MC noise (0.2-2.6 %) is added at 3 sigma.
        const double tol = sc.tol[di] + 3.0 * m.total.std_error / m.total.mean;
        EXPECT_LT(std::abs(gpu_err), tol) << sc.name << " " << dir.name << " ch " << c << " (GPU)";
      }
    }
  }
  std::printf("Monte Carlo: %lld paths per estimate, %.1f s wall in total\n", mcs.paths, mc_seconds);
}

}  // namespace
}  // namespace cloudsvc::test
