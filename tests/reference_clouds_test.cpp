// The reference's cloud pieces: the scene set-up (wind rotation, camera, shell), the
// density field and the lighting terms, against hand-computed values and limits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "renderer/model/mie_phase_table.h"
#include "renderer/model/ms_source_table.h"
#include "renderer/model/phase_function.h"
#include "renderer/reference/cloud_field.h"
#include "renderer/reference/cloud_lighting.h"
#include "renderer/reference/reference_scene.h"

namespace cloudsvc::reference {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(ReferenceScene, CalmWindIsIdentityAndTheFieldMovesWithTheWind) {
  const WindAnchor anchor{{47.45, 8.56, 1500.0}, 1.7e9};
  const glm::dmat3 calm = field_rotation({0.0, 0.0}, anchor, anchor.unix_time_s + 3600.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(calm[i][j], i == j ? 1.0 : 0.0);
  // One minute of 10 m/s wind from the west: the field point now 600 m downwind of the
  // anchor (along the sphere) samples what was at the anchor.
  const weather::Wind west{10.0, 0.0};
  const glm::dmat3 r = field_rotation(west, anchor, anchor.unix_time_s + 60.0);
  const glm::dvec3 p0 = geo::geodetic_to_ecef(anchor.position);
  const glm::dvec3 east = geo::enu_to_ecef(47.45, 8.56)[0];
  const glm::dvec3 axis = glm::normalize(glm::cross(p0, east));
  const double angle = 600.0 / glm::length(p0);
  // p0 rotated by +angle about the axis (Rodrigues), i.e. carried 600 m along the wind.
  const glm::dvec3 moved = p0 * std::cos(angle) + glm::cross(axis, p0) * std::sin(angle) +
                           axis * glm::dot(axis, p0) * (1.0 - std::cos(angle));
  EXPECT_LT(glm::length(r * moved - p0), 1e-6) << "metres";
  EXPECT_NEAR(glm::length(moved - p0), 600.0, 0.01);
  // Orthonormal after 30 days.
  const glm::dmat3 month = field_rotation({35.0, -12.0}, anchor, anchor.unix_time_s + 30.0 * 86400.0);
  const glm::dmat3 rtr = glm::transpose(month) * month;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(rtr[i][j], i == j ? 1.0 : 0.0, 1e-12);
}

ViewRequest level_view(double lat, double alt) {
  ViewRequest v;
  v.position = {lat, 8.0, alt};
  v.attitude = {90.0, 0.0, 0.0};  // east, level
  v.unix_time_s = 1.78e9;
  v.width = 100;
  v.height = 50;
  v.fov_deg = 90.0;
  return v;
}

TEST(ReferenceScene, CameraRaysAndShellGeometry) {
  const ReferenceScene s = make_reference_scene(level_view(47.45, 2000.0), weather::Weather{});
  // The centre of the image looks east (rows from the top: pixel (0, 0) is up-left).
  const glm::dvec3 c = glm::normalize(s.camera.ray_at(49.5, 24.5) + s.camera.ray_at(50.5, 25.5));
  EXPECT_NEAR(c.x, 1.0, 1e-9);
  const glm::dvec3 top_left = s.camera.ray_at(0.5, 0.5);
  EXPECT_GT(top_left.y, 0.0);        // left of east is north
  EXPECT_GT(top_left.z, 0.0);        // top row looks up
  EXPECT_NEAR(s.camera.window.half_x, 1.0, 1e-12);
  EXPECT_NEAR(s.camera.window.half_y, 0.5, 1e-12);
  EXPECT_EQ(s.camera.window.center_x, 0.0);
  // Osculating radius sqrt(M N) at 47.45 deg, camera at 2 km above it, ground at 0.
  EXPECT_NEAR(s.shell.radius_m, std::sqrt(geo::meridional_radius(47.45) * geo::prime_vertical_radius(47.45)), 1e-6);
  EXPECT_NEAR(s.shell.altitude_of(glm::dvec3(0.0)), 2000.0, 1e-6);
  EXPECT_EQ(s.shell.ground_alt_m, 0.0);
  // 10 km east, level: the sphere drops away by d^2 / 2R ~ 7.85 m.
  EXPECT_NEAR(s.shell.altitude_of({10000.0, 0.0, 0.0}) - 2000.0, 1.0e8 / (2.0 * (s.shell.radius_m + 2000.0)), 1e-3);
  // A camera below the ellipsoid puts the ground 1 m below it.
  EXPECT_EQ(make_reference_scene(level_view(10.0, -30.0), weather::Weather{}).shell.ground_alt_m, -31.0);
}

weather::Weather one_layer(weather::CloudType type, double base, double top, double coverage) {
  weather::Weather w;
  weather::CloudLayer l = weather::default_layer(type);
  l.base_m = base;
  l.top_m = top;
  l.coverage = coverage;
  w.layers.push_back(l);
  w.map_seed = 11;
  return w;
}

TEST(ReferenceClouds, HeightProfileByHand) {
  ReferenceLayer sc;
  sc.bottom_ramp = 0.15;
  sc.top_ramp = 0.3;
  sc.top_weight = 0.0;
  EXPECT_EQ(CloudField::height_profile(sc, 0.0), 0.0);
  EXPECT_EQ(CloudField::height_profile(sc, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(CloudField::height_profile(sc, 0.5), 1.0);
  // Half-way up the bottom ramp: smoothstep(0.5) = 0.5.
  EXPECT_NEAR(CloudField::height_profile(sc, 0.075), 0.5, 1e-12);
  ReferenceLayer cb = sc;
  cb.top_weight = 0.6;  // mix(1, x, 0.6) at x = 0.5: 0.7
  EXPECT_NEAR(CloudField::height_profile(cb, 0.5), 0.7, 1e-12);
}

// Coverage is an area fraction: at mid-layer, where the profile is 1, the fraction of a
// large horizontal area with cloud follows the local coverage (weather map included).
TEST(ReferenceClouds, CoverageIsTheCloudyAreaFraction) {
  for (double coverage : {0.3, 0.7}) {
    const weather::Weather w = one_layer(weather::CloudType::Stratocumulus, 1000.0, 2000.0, coverage);
    const ReferenceScene s = make_reference_scene(level_view(47.45, 1500.0), w);
    const auto inputs = reference_inputs(InputConfig{}, w.map_seed);
    const CloudField field(s, *inputs);
    std::uint64_t evals = 0;
    int cloudy = 0, n = 0;
    double mean_local_coverage = 0.0;
    for (int i = 0; i < 200; ++i)
      for (int j = 0; j < 200; ++j) {
        const glm::dvec3 p(-30000.0 + 300.0 * i + 7.0, -30000.0 + 300.0 * j + 3.0, 0.0);
        const glm::dvec3 q = p + glm::dvec3(0.0, 0.0, 1500.0 - s.shell.altitude_of(p));  // at 1500 m
        const CloudSample c = field.sample(0, q, s.shell.altitude_of(q), false, evals);  // base shape only
        cloudy += c.sigma_t > 0.0;
        mean_local_coverage += c.coverage;
        ++n;
      }
    mean_local_coverage /= n;
    const double fraction = static_cast<double>(cloudy) / n;
    std::printf("coverage %.2f: local coverage %.3f, cloudy fraction at mid-layer %.3f\n", coverage,
                mean_local_coverage, fraction);
    EXPECT_NEAR(fraction, mean_local_coverage, 0.08);
    EXPECT_EQ(evals, static_cast<std::uint64_t>(n));
  }
}

TEST(ReferenceClouds, NothingOutsideTheLayerOrAtZeroCoverage) {
  const weather::Weather w = one_layer(weather::CloudType::Stratus, 400.0, 900.0, 1.0);
  const ReferenceScene s = make_reference_scene(level_view(47.45, 650.0), w);
  const auto inputs = reference_inputs(InputConfig{}, w.map_seed);
  const CloudField field(s, *inputs);
  std::uint64_t evals = 0;
  EXPECT_EQ(field.sample(0, {0, 0, 300.0}, 950.0, true, evals).sigma_t, 0.0);
  EXPECT_EQ(field.sample(0, {0, 0, -300.0}, 350.0, true, evals).sigma_t, 0.0);
  EXPECT_EQ(evals, 0u) << "points outside the layer are not density evaluations";
  // Overcast stratus: the extinction at mid-layer is positive and bounded by the peak
  // sigma_max * density_scale * 2.
  const double peak = s.layers[0].sigma_max_per_m * s.layers[0].density_scale * 2.0;
  const double sigma = field.sample(0, {0, 0, 0}, 650.0, true, evals).sigma_t;
  EXPECT_GT(sigma, 0.0);
  EXPECT_LE(sigma, peak);
  ReferenceScene clear_scene = s;
  clear_scene.layers[0].coverage = 0.0;
  const CloudField clear(clear_scene, *inputs);
  EXPECT_EQ(clear.sample(0, {0, 0, 0}, 650.0, true, evals).sigma_t, 0.0);
}

// The light march converges: 10 m steps agree with 1 m steps to 0.5 % in optical depth.
TEST(ReferenceClouds, LightMarchConverges) {
  const weather::Weather w = one_layer(weather::CloudType::Stratocumulus, 1200.0, 1800.0, 0.85);
  const ReferenceScene s = make_reference_scene(level_view(47.45, 1300.0), w);
  const auto inputs = reference_inputs(InputConfig{}, w.map_seed);
  const CloudField field(s, *inputs);
  std::uint64_t evals = 0;
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.3, 0.2, 0.6));
  double coarse_sum = 0.0, fine_sum = 0.0, worst = 0.0;
  for (int i = 0; i < 20; ++i) {
    const glm::dvec3 p(137.0 * i, -91.0 * i, 0.0);
    const double alt = s.shell.altitude_of(p);
    const double mu_s = glm::dot(s.shell.up_at(p), sun);
    const double coarse = light_optical_depth(field, 0, p, alt, sun, mu_s, 10.0, 1e9, evals);
    const double fine = light_optical_depth(field, 0, p, alt, sun, mu_s, 1.0, 1e9, evals);
    coarse_sum += coarse;
    fine_sum += fine;
    if (fine > 1.0) worst = std::max(worst, std::abs(coarse / fine - 1.0));
  }
  std::printf("light optical depth, 10 m vs 1 m steps: mean %.3f vs %.3f, worst relative %.2e\n", coarse_sum / 20,
              fine_sum / 20, worst);
  EXPECT_GT(fine_sum, 20.0);
  EXPECT_LT(worst, 0.005);
}

// The diffuse light's depths are those of the point's own column: along one vertical they
// add up to the same column total wherever the point is, they converge with the step, and
// in a cumulus field they differ from column to column (clear gaps hold none) where a
// homogeneous layer of the map's coverage would give every point of one altitude the same.
TEST(ReferenceClouds, ColumnDepthsAreThePointsOwnColumn) {
  const weather::Weather w = one_layer(weather::CloudType::Cumulus, 1200.0, 2400.0, 0.45);
  const ReferenceScene s = make_reference_scene(level_view(47.45, 1000.0), w);
  const auto inputs = reference_inputs(InputConfig{}, w.map_seed);
  const CloudField field(s, *inputs);
  std::uint64_t evals = 0;
  double least = 1e30, most = 0.0, worst_total = 0.0, worst_step = 0.0;
  for (int i = 0; i < 40; ++i) {
    // a vertical line through the layer at a horizontal position 211 m further each time
    const glm::dvec3 base_point(211.0 * i, -97.0 * i, 0.0);
    const glm::dvec3 up = s.shell.up_at(base_point);
    const double base_alt = s.shell.altitude_of(base_point);
    double total0 = -1.0;
    for (const double h : {1300.0, 1800.0, 2300.0}) {
      const glm::dvec3 p = base_point + up * (h - base_alt);
      const double alt = s.shell.altitude_of(p);
      const ColumnDepths c = column_optical_depths(field, 0, p, alt, 2.0, evals);
      const ColumnDepths fine = column_optical_depths(field, 0, p, alt, 0.5, evals);
      EXPECT_GE(c.above, 0.0);
      EXPECT_GE(c.below, 0.0);
      const double total = c.above + c.below;
      if (total0 < 0.0) total0 = total;
      if (total0 > 1.0) worst_total = std::max(worst_total, std::abs(total / total0 - 1.0));
      if (fine.above > 1.0) worst_step = std::max(worst_step, std::abs(c.above / fine.above - 1.0));
    }
    least = std::min(least, total0);
    most = std::max(most, total0);
  }
  std::printf("column optical depth over 40 columns: %.2f .. %.2f; worst spread along a column %.2e, "
              "2 m vs 0.5 m steps %.2e\n", least, most, worst_total, worst_step);
  EXPECT_LT(worst_total, 0.01);  // one column, one total (up to the midpoint rule's error)
  EXPECT_LT(worst_step, 0.01);
  EXPECT_LT(least, 0.1);  // a gap between the cumulus
  EXPECT_GT(most, 10.0);  // a cloud's column
}

TEST(ReferenceClouds, SunPhaseIsThePeakBeam) {
  const model::JdDParams p = model::jdd_params(20.0);
  // No shadow: the phase function itself; in shadow, the peak beam.
  EXPECT_NEAR(sun_phase(p, nullptr, 0.3, 0.0).g, model::jdd_phase(0.3, p), 1e-12);
  EXPECT_NEAR(sun_phase(p, nullptr, -0.2, 7.0).b, model::peak_beam_phase(-0.2, 7.0, p), 1e-15);
  // With the Mie table: single scattering is the table's (per wavelength), the peak
  // orders beyond it the fit's.
  const std::shared_ptr<const model::PhaseTable> mie = model::mie_phase_table(10.0);
  const double tau = 1.5;
  const glm::dvec3 with_mie = sun_phase(p, mie.get(), -0.2, tau);
  const glm::dvec3 expected = mie->at_cos(-0.2) * std::exp(-tau) + glm::dvec3(model::peak_beam_phase(-0.2, tau, p) -
                                                                               model::jdd_phase(-0.2, p) * std::exp(-tau));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(with_mie[c], expected[c], 1e-12);
  EXPECT_NE(with_mie.r, with_mie.b);  // the table is spectral
}

TEST(ReferenceClouds, DiffuseInscatterByHand) {
  ReferenceLayer L;
  L.base_m = 1000.0;
  L.top_m = 2000.0;
  L.sigma_max_per_m = 0.05;
  L.density_scale = 1.0;
  L.phase = model::jdd_params(model::kMsTableDropletUm);  // similarity scale 1
  const glm::dvec3 e_sun(2.0), t_atm(0.8), e_sky(0.1), t_ground(0.7), e_sky_ground(0.12), albedo(0.1);
  const double mu_s = 0.5, coverage = 0.4;
  const ColumnDepths column{10.0, 10.0};  // the point's column: optical depth 10 above and below
  const double E_sky = 2.0 * 0.1;
  // The ground under the layer as independent columns: 0.6 of it in the clear, 0.4 under the
  // layer's full optical depth (0.05 /m over 1000 m: 50), sun and sky at ground level, with
  // the round trips between ground and cloud, 1 / (1 - 0.4 a (1 - T(50))); it sends up a
  // times that. The sun's beam through the layer: the table's beam transmittance.
  const double T50 = model::slab_diffuse_transmittance(50.0);
  const double T_beam50 = model::slab_beam_transmittance(50.0, 0.5);
  const double gain = 1.0 / (1.0 - 0.4 * 0.1 * (1.0 - T50));
  EXPECT_NEAR(ground_cloud_gain(0.4 * albedo, 50.0).g, gain, 1e-12);
  EXPECT_NEAR(ground_cloud_gain(glm::dvec3(0.8), 0.0).g, 1.0, 1e-12);  // no cloud: no round trips
  EXPECT_NEAR(slab_beam_transmittance(0.0, 0.3), 1.0, 1e-12);           // nothing in the way
  const double E_up = 0.1 * gain * 2.0 * (0.7 * 0.5 * (0.6 + 0.4 * T_beam50) + 0.12 * (0.6 + 0.4 * T50));
  // the sky's light enters through the top, the ground's through the base: the diffuse
  // incidence table, the base's turned upside down (at mid-depth: the same column mirrored)
  const double w_up = -0.6, cos_phi = 0.3;
  const model::MsSourceTable& iso = model::ms_diffuse_incidence_table();
  const double down = iso.lookup(10.0, 10.0, 1.0, w_up, 0.0), up = iso.lookup(10.0, 10.0, 1.0, -w_up, 0.0);
  EXPECT_GT(down, up);  // more of the sky's light goes on down
  const double diffuse = E_sky * down + E_up * up;
  // the sun's: the source table times the horizontal solar flux F_sun = 2 * 0.8 * 0.5
  const double table = model::ms_source_table().lookup(10.0, 10.0, mu_s, w_up, std::acos(cos_phi) * 180.0 / kPi);
  EXPECT_GT(table, 0.0);
  const glm::dvec3 got =
      diffuse_inscatter(L, column, SunSlab{mu_s, column.above, column.below, w_up, cos_phi}, mu_s, coverage, e_sun, t_atm, e_sky,
                        t_ground, e_sky_ground, albedo, w_up);
  EXPECT_NEAR(got.g, 2.0 * 0.8 * 0.5 * table + diffuse, 1e-12);
  // Looking up into the cloud (light travelling down) is brighter than looking down onto
  // it from its middle: more of the sun's light travels down there.
  const glm::dvec3 from_below =
      diffuse_inscatter(L, column, SunSlab{mu_s, column.above, column.below, -1.0, 1.0}, mu_s, coverage, e_sun, t_atm, e_sky,
                        t_ground, e_sky_ground, albedo, -1.0);
  const glm::dvec3 from_above =
      diffuse_inscatter(L, column, SunSlab{mu_s, column.above, column.below, 1.0, 1.0}, mu_s, coverage, e_sun, t_atm, e_sky,
                        t_ground, e_sky_ground, albedo, 1.0);
  EXPECT_GT(from_below.g, from_above.g);
  EXPECT_GE(from_above.g, 0.0);
  // Sun below the horizon: no sun term, sky light only (isotropic view, w_up = 0).
  const glm::dvec3 night = diffuse_inscatter(L, column, SunSlab{-0.1, column.above, column.below, 0.0, 1.0}, -0.1, coverage, e_sun,
                                             glm::dvec3(0.0), e_sky, glm::dvec3(0.0), e_sky_ground, albedo, 0.0);
  const double E_up_night = 0.1 * gain * 2.0 * 0.12 * (0.6 + 0.4 * T50);
  EXPECT_NEAR(night.r, (E_sky + E_up_night) * iso.lookup(10.0, 10.0, 1.0, 0.0, 0.0), 1e-12);
}

// The sun's slab tilted towards the sun (tilted_sun_slab): the horizontal slab wherever the
// sun's depth is that of a horizontally homogeneous layer, the sun's own face where the sun's
// path leaves the cloud at once, and never shallower than the column where a neighbour
// shades the point.
TEST(ReferenceClouds, TheSunsSlabTiltsOnlyWhereTheSunsPathLeavesTheCloudEarly) {
  const glm::dvec3 up(0.0, 0.0, 1.0);
  const double mu_s = 0.2;  // sun 11.5 deg above the horizon, towards +x
  const glm::dvec3 sun(std::sqrt(1.0 - mu_s * mu_s), 0.0, mu_s);
  const glm::dvec3 w = glm::normalize(glm::dvec3(-0.3, 0.5, 0.6));  // scattered light, towards the camera
  const ColumnDepths column{12.0, 30.0};
  const SunSlab flat = vertical_sun_slab(column, up, sun, w);
  EXPECT_DOUBLE_EQ(flat.mu, mu_s);
  EXPECT_DOUBLE_EQ(flat.above, 12.0);
  EXPECT_DOUBLE_EQ(flat.below, 30.0);
  EXPECT_DOUBLE_EQ(flat.w_n, glm::dot(w, up));
  // A homogeneous layer: the sun's path to the top is tau_a / mu_s deep; over half of it (a
  // march stopped at its reach), half as deep with window 0.5.
  for (const double window : {1.0, 0.5}) {
    const SunSlab s = tilted_sun_slab(column, window * 12.0 / mu_s, window, up, sun, w);
    EXPECT_NEAR(s.mu, mu_s, 1e-12) << window;
    EXPECT_NEAR(s.above, 12.0, 1e-12) << window;
    EXPECT_NEAR(s.below, 30.0, 1e-12) << window;
    EXPECT_NEAR(s.w_n, flat.w_n, 1e-12) << window;
    EXPECT_NEAR(s.cos_phi, flat.cos_phi, 1e-12) << window;
  }
  // The sun's path leaves the cloud after an optical depth of 1 (through its side): the face
  // looks at the sun; the point is 1 deep, the column's cloud lies behind it.
  const SunSlab side = tilted_sun_slab(column, 1.0, 1.0, up, sun, w);
  EXPECT_DOUBLE_EQ(side.mu, 1.0);
  EXPECT_NEAR(side.above, 1.0, 1e-12);
  EXPECT_NEAR(side.below, 30.0 + 12.0 - 1.0, 1e-12);
  EXPECT_NEAR(side.w_n, glm::dot(w, sun), 1e-12);  // the normal is the sun's direction
  // Between the two: the cosine grows as the path gets shallower, and the point's depth along
  // the normal stays that of its column.
  const SunSlab half = tilted_sun_slab(column, 0.5 * 12.0 / mu_s, 1.0, up, sun, w);
  EXPECT_NEAR(half.mu, 2.0 * mu_s, 1e-12);
  EXPECT_NEAR(half.above, 12.0, 1e-12);
  // A neighbour shades the point (twice the horizontal slab's depth): the slab stays
  // horizontal but as deep as the sun's path says.
  const SunSlab shaded = tilted_sun_slab(column, 2.0 * 12.0 / mu_s, 1.0, up, sun, w);
  EXPECT_NEAR(shaded.mu, mu_s, 1e-12);
  EXPECT_NEAR(shaded.above, 24.0, 1e-12);
  EXPECT_NEAR(shaded.below, 30.0, 1e-12);
  // No sun, or the sun overhead: the horizontal slab whatever the depths.
  const glm::dvec3 below_horizon = glm::normalize(glm::dvec3(1.0, 0.0, -0.05));
  EXPECT_DOUBLE_EQ(tilted_sun_slab(column, 0.0, 1.0, up, below_horizon, w).above, 12.0);
  EXPECT_DOUBLE_EQ(tilted_sun_slab(column, 0.0, 1.0, up, up, w).mu, 1.0);
  EXPECT_DOUBLE_EQ(tilted_sun_slab(column, 0.0, 1.0, up, up, w).above, 12.0);
  // The window: the vertical span of the marched path over the column above, at most 1.
  EXPECT_DOUBLE_EQ(sun_window(1000.0, 0.2, 400.0), 0.5);
  EXPECT_DOUBLE_EQ(sun_window(4000.0, 0.2, 400.0), 1.0);
  EXPECT_DOUBLE_EQ(sun_window(0.0, 0.2, 400.0), 0.0);
  EXPECT_DOUBLE_EQ(sun_window(100.0, 0.2, 0.0), 1.0);  // at the top
}

// The sunlit face of a cloud under a low sun receives the sun's flux at a cosine near 1: its
// diffuse light is several times the horizontal slab's there.
TEST(ReferenceClouds, ALowSunLightsTheFaceThatLooksAtIt) {
  ReferenceLayer L;
  L.phase = model::jdd_params(20.0);
  const glm::dvec3 up(0.0, 0.0, 1.0);
  const double mu_s = 0.15;
  const glm::dvec3 sun(std::sqrt(1.0 - mu_s * mu_s), 0.0, mu_s);
  const glm::dvec3 w = glm::normalize(glm::dvec3(1.0, 0.2, 0.3));  // seen from the sun's side
  const ColumnDepths column{20.0, 20.0};
  const glm::dvec3 e_sun(1.0), t_atm(1.0), zero(0.0);
  const auto sun_part = [&](const SunSlab& slab) {
    return diffuse_inscatter(L, column, slab, mu_s, 1.0, e_sun, t_atm, zero, zero, zero, zero, glm::dot(w, up)).g;
  };
  const double flat = sun_part(vertical_sun_slab(column, up, sun, w));
  const double face = sun_part(tilted_sun_slab(column, 0.5, 1.0, up, sun, w));
  std::printf("diffuse light 0.5 deep behind the sunlit face: %.4f, the horizontal slab's at 20 deep: %.4f\n", face,
              flat);
  EXPECT_GT(flat, 0.0);
  EXPECT_GT(face, 3.0 * flat);
  // ... and the horizontal slab's own top, 0.5 deep under the same low sun, is dimmer than
  // the face.
  const ColumnDepths top{0.5, 39.5};
  const SunSlab top_slab = vertical_sun_slab(top, up, sun, w);
  EXPECT_GT(face, diffuse_inscatter(L, top, top_slab, mu_s, 1.0, e_sun, t_atm, zero, zero, zero, zero, glm::dot(w, up)).g);
}

TEST(ReferenceClouds, LayerStepScale) {
  const ReferenceScene s = make_reference_scene(
      level_view(47.45, 0.0), [] {
        weather::Weather w;
        w.layers = {weather::default_layer(weather::CloudType::Cumulus), weather::default_layer(weather::CloudType::Cirrus)};
        w.layers[1].base_m = 9000.0;
        w.layers[1].top_m = 10000.0;
        return w;
      }());
  EXPECT_NEAR(layer_step_scale(s.layers[0]), 1.0, 0.01);  // cumulus: the base steps
  EXPECT_EQ(layer_step_scale(s.layers[1]), 5.0);           // cirrus: 40 km period, optically thin
}

}  // namespace
}  // namespace cloudsvc::reference
