// The glory and the fogbow in the GPU image (RendererConfig::cloud_phase = kMie,
// renderer/model/mie_phase_table.h): seen from above an overcast stratus deck with the sun
// behind the camera, the image's rings around the antisolar point sit where the droplets'
// Mie phase function has them, and the GPU agrees with the CPU reference.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "antisolar_profile.h"
#include "render_test_support.h"
#include "renderer/model/phase_function.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/image_metrics.h"
#include "renderer/reference/reference_renderer.h"

namespace cloudsvc::test {
namespace {

CloudRenderer& mie_renderer() {
  shared_renderer();  // the GL context
  static std::unique_ptr<CloudRenderer> r = [] {
    RendererConfig c;
    c.cloud_phase = model::CloudPhaseModel::kMie;
    return std::make_unique<CloudRenderer>(c);
  }();
  return *r;
}

weather::Weather deck(double droplet_diameter_um) {
  weather::Weather w = single_layer(weather::CloudType::Stratus, 400.0, 900.0, 1.0);
  w.layers[0].droplet_diameter_um = droplet_diameter_um;
  return w;
}

// A camera 2 km up over Zurich on 2026-06-21 at 10:00 UTC (sun 60 deg high) looking at the
// antisolar point.
ViewRequest antisolar_view(const weather::Weather& w, int size, double fov_deg) {
  ViewRequest v = make_view(47.45, 8.56, 2000.0, 0.0, 0.0, "2026-06-21T10:00Z", size, size, fov_deg);
  const reference::ReferenceScene s = reference::make_reference_scene(v, w);
  v.attitude.heading_deg = std::fmod(s.sun_azimuth_deg + 180.0, 360.0);
  v.attitude.pitch_deg = -s.sun_elevation_deg;
  return v;
}

FrameImage render_deck(CloudRenderer& r, const weather::Weather& w, const ViewRequest& v) {
  r.set_weather(w);
  const FrameImage img = render_still_view(r, v, *quality_preset("default"));
  EXPECT_EQ(img.stats.nonfinite_pixels, 0);
  return img;
}

// The first glory ring, 12 deg across at 160 px (0.075 deg per pixel): the image's maximum
// within 0.5 deg of Mie's ring, per channel, lies within 0.3 deg of it.
TEST(MiePhaseImage, GloryRingsSitWhereMieHasThem) {
  for (double d : {10.0, 20.0}) {
    const weather::Weather w = deck(d);
    const ViewRequest v = antisolar_view(w, 160, 12.0);
    const FrameImage img = render_deck(mie_renderer(), w, v);
    maybe_save("mie_glory_" + std::to_string(static_cast<int>(d)), img);
    const AntisolarProfile p = antisolar_profile(img, reference::make_reference_scene(v, w), 0.05, 6.0);
    const std::shared_ptr<const model::PhaseTable> t = model::mie_phase_table(d);
    double seen[3];
    for (int c = 0; c < 3; ++c) {
      const double mie = glory_first_ring_deg(*t, c);
      seen[c] = profile_maximum_deg(p, c, mie - 0.5, mie + 0.5);
      std::printf("d %.0f um, channel %d: first glory ring %.2f deg from the antisolar point (Mie), %.2f deg (image)\n",
                  d, c, mie, seen[c]);
      EXPECT_NEAR(seen[c], mie, 0.3) << "d " << d << " channel " << c;
    }
    EXPECT_GT(seen[0], seen[2]) << "red outside blue";
  }
}

// The fogbow, 100 deg across at 200 px. The deck's multiply scattered light falls off with
// the angle from the antisolar point, which moves the image's own maximum inwards (printed;
// 0.2-2.2 deg for these droplets); the single-scattered bow is what the phase function
// decides: the image with the Mie table minus the image with the fit holds it (the rest of
// the light is the same), and its maximum lies within 0.3 deg of the maximum of
// p_Mie - p_fit.
TEST(MiePhaseImage, FogbowSitsWhereMieHasIt) {
  for (double d : {10.0, 20.0}) {
    const weather::Weather w = deck(d);
    const ViewRequest v = antisolar_view(w, 200, 100.0);
    const reference::ReferenceScene scene = reference::make_reference_scene(v, w);
    const FrameImage mie = render_deck(mie_renderer(), w, v);
    const FrameImage fit = render_deck(shared_renderer(), w, v);
    maybe_save("mie_fogbow_" + std::to_string(static_cast<int>(d)), mie);
    const AntisolarProfile pm = antisolar_profile(mie, scene, 0.25, 50.0), pf = antisolar_profile(fit, scene, 0.25, 50.0);
    AntisolarProfile diff = pm;
    for (std::size_t k = 0; k < pm.mean.size(); ++k) diff.mean[k] = pm.mean[k] - pf.mean[k];
    const std::shared_ptr<const model::PhaseTable> t = model::mie_phase_table(d);
    const model::JdDParams jdd = model::jdd_params(d);
    for (int c = 0; c < 3; ++c) {
      const double step = 0.01;
      const double table_diff =
          step * parabolic_maximum(
                     [&](int i) {
                       const double theta = 180.0 - i * step;
                       return t->at_angle_deg(theta)[c] - model::jdd_phase(std::cos(theta * M_PI / 180.0), jdd);
                     },
                     static_cast<int>(25.0 / step), static_cast<int>(48.0 / step));
      const double image_diff = profile_maximum_deg(diff, c, 25.0, 48.0);
      std::printf("d %.0f um, channel %d: fogbow %.2f deg (Mie), image %.2f deg; Mie - fit %.2f deg, image difference "
                  "%.2f deg\n",
                  d, c, table_maximum_deg(*t, c, 25.0, 48.0), profile_maximum_deg(pm, c, 25.0, 48.0), table_diff,
                  image_diff);
      EXPECT_NEAR(image_diff, table_diff, 0.3) << "d " << d << " channel " << c;
    }
  }
}

// The GPU's default preset against the CPU reference with the same Mie tables, on the glory
// view at 48 x 48.
TEST(MiePhaseImage, AgreesWithTheReference) {
  const weather::Weather w = deck(20.0);
  const ViewRequest v = antisolar_view(w, 48, 12.0);
  reference::ReferenceSettings settings;
  settings.cloud_phase = model::CloudPhaseModel::kMie;
  const FrameImage ref = reference::render_reference(v, w, settings);
  const FrameImage gpu = render_deck(mie_renderer(), w, v);
  const FrameImage fit = render_deck(shared_renderer(), w, v);
  const reference::ImageDifference c = reference::compare_images(gpu, ref), cf = reference::compare_images(fit, ref);
  const double mean = mean_luminance(ref);
  std::printf("GPU (Mie) vs reference (Mie): RMSE %.2e (%.2f %% of the mean); GPU with the fit vs it: %.2f %%\n", c.rmse,
              100.0 * c.rmse / mean, 100.0 * cf.rmse / mean);
  EXPECT_LT(c.rmse, 0.01 * mean);
  EXPECT_GT(cf.rmse, 2.0 * c.rmse);  // the phase functions differ visibly at the glory
}

// The service's renderer (wait_for_phase_tables off) draws a new droplet size with the fit
// while its Mie table is computed (FrameStats::phase_tables_pending), and with the table
// once it is ready; no frame waits for it.
TEST(MiePhaseImage, WithoutWaitingTheFitStandsInUntilTheTableIsReady) {
  shared_renderer();  // the GL context
  RendererConfig c;
  c.cloud_phase = model::CloudPhaseModel::kMie;
  c.wait_for_phase_tables = false;
  CloudRenderer service(c);
  const weather::Weather w = deck(16.7);  // a diameter no other test asks for
  const ViewRequest v = antisolar_view(w, 32, 12.0);
  const FrameImage before = render_deck(service, w, v);
  const FrameImage fit = render_deck(shared_renderer(), w, v);
  std::printf("first frames: %d table(s) pending, RMSE against the fit %.2e\n", before.stats.phase_tables_pending,
              reference::compare_images(before, fit).rmse);
  if (before.stats.phase_tables_pending == 1) {  // (the table takes seconds, the frames milliseconds)
    EXPECT_LT(reference::compare_images(before, fit).rmse, 1e-4 * mean_luminance(fit));
  }
  model::mie_phase_table(16.7);  // waits for the table
  const FrameImage after = render_deck(service, w, v);
  const FrameImage waited = render_deck(mie_renderer(), w, v);
  EXPECT_EQ(after.stats.phase_tables_pending, 0);
  EXPECT_LT(reference::compare_images(after, waited).rmse, 1e-4 * mean_luminance(waited));
  EXPECT_GT(reference::compare_images(after, fit).rmse, 10.0 * reference::compare_images(after, waited).rmse);
}

}  // namespace
}  // namespace cloudsvc::test
