// slab_mc_table: the renderer's light model against Monte Carlo radiative transfer in a
// homogeneous conservative slab (issue "Accuracy", independent physical checks:
// multiple scattering). For optical depths 1..100 and sun zeniths 0..80° it prints
// Markdown tables of the radiance reflected (camera above, looking down) and transmitted
// (camera below, looking up) at view zenith 0° and 60° in the solar plane:
//   MC ± standard error (renderer/model/slab_monte_carlo.h, exact transport),
//   the renderer model with converged steps and at the shader's default 64 steps
//   (renderer/model/slab_renderer_model.h, a transcription of shaders/cloud_march.comp),
//   relative errors (model - MC) / MC.
// Radiances are L / E_sun in sr^-1 (E_sun normal to the beam); droplet diameter 14 um.
//
//   build/bin/slab_mc_table [--scale 1] [--threads 0] [--seed 1]   (--threads 0: all cores)
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "common/parallel_for.h"
#include "renderer/model/droplet_optics.h"
#include "renderer/model/phase_function.h"
#include "renderer/model/slab_monte_carlo.h"
#include "renderer/model/slab_renderer_model.h"

namespace {

using namespace cloudsvc::model;

struct ViewCase {
  const char* name;
  ViewDirection v;
};

// View zenith 0; 60° in the solar plane, the observer looking away from the sun (light
// azimuth 0: backscatter side from above, the cloud base opposite the sun from below)
// and looking towards the sun (azimuth 180: forward-scatter side from above, the
// aureole side from below; at sun zenith 60 the latter view looks straight at the sun).
const ViewCase kViews[] = {{"0", {0.0, 0.0}}, {"60 away from sun", {60.0, 0.0}}, {"60 towards sun", {60.0, 180.0}}};

struct Row {
  double tau, sun;
  SlabMcResult mc;
  std::vector<double> model_top, model_bottom, model64_top, model64_bottom;
};

std::string rel(double model, double mc) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.0f %%", 100.0 * (model - mc) / mc);
  return buf;
}

void print_table(const std::vector<Row>& rows, bool top) {
  std::printf("\n### %s radiance (L / E_sun, sr^-1)\n\n", top ? "Reflected (top, camera above)" : "Transmitted (bottom, camera below, direct sun excluded)");
  std::printf("| tau | sun | view | MC ± se | model (converged) | err | model (64 steps) | err |\n");
  std::printf("|---:|---:|---|---:|---:|---:|---:|---:|\n");
  for (const Row& r : rows) {
    for (size_t k = 0; k < std::size(kViews); ++k) {
      const Estimate& e = top ? r.mc.radiance_top[k] : r.mc.radiance_bottom[k];
      const double m = top ? r.model_top[k] : r.model_bottom[k];
      const double m64 = top ? r.model64_top[k] : r.model64_bottom[k];
      std::printf("| %g | %g | %s | %.4g ± %.2g | %.4g | %s | %.4g | %s |\n", r.tau, r.sun, kViews[k].name, e.mean,
                  e.std_error, m, rel(m, e.mean).c_str(), m64, rel(m64, e.mean).c_str());
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Renderer light model vs Monte Carlo in a homogeneous conservative cloud slab (Markdown tables)"};
  double scale = 1.0;
  int threads = cloudsvc::kAllThreads;
  std::uint64_t seed = 1;
  std::vector<double> taus = {1, 2, 4, 8, 16, 32, 64, 100};
  std::vector<double> suns = {0, 30, 60, 80};
  app.add_option("--scale", scale, "photon count multiplier (1: a few minutes on 2 cores)")->check(CLI::Range(0.001, 1000.0));
  app.add_option("--threads", threads, "worker threads (0: all cores; the tables do not depend on it)")
      ->check(CLI::Range(0, 256));
  app.add_option("--seed", seed, "random seed");
  app.add_option("--tau", taus, "optical depths")->check(CLI::Range(0.01, 1000.0));
  app.add_option("--sun", suns, "sun zenith angles, degrees")->check(CLI::Range(0.0, 85.0));
  bool ms_column = false;
  double ms_scale = 1.0;
  app.add_flag("--ms-source-column", ms_column,
               "renderer model: the diffuse source from a Monte Carlo column computed for each case instead of the "
               "table's interpolation (tells the light model's error from the table's)");
  app.add_option("--ms-source-scale", ms_scale, "photon multiplier of those columns")->check(CLI::Range(0.001, 1000.0));
  CLI11_PARSE(app, argc, argv);

  const auto t0 = std::chrono::steady_clock::now();
  const double d_um = 14.0;
  std::printf("## Slab multiple scattering: renderer model vs Monte Carlo\n\n");
  std::printf("Homogeneous conservative slab, JdD phase for d = %g um (mean cosine %.4f), sigma_t = %.4g 1/m "
              "(N0 = 300 cm^-3, Q_ext = 2), black ground, no atmosphere, E_sun = 1. Renderer model: the peak beam "
              "(single scattering and the light scattered only through the diffraction peak) over the light march, "
              "capped at 4 km, plus the diffuse source %s (renderer/model/ms_source_table.h); converged = 4096 "
              "primary steps, 64 steps = shader default (jitter-averaged). err = (model - MC) / MC. View 60 in the "
              "solar plane, observer looking away from / towards the sun.\n",
              d_um, jdd_mean_cosine(jdd_params(d_um)), cloud_extinction_per_m(d_um),
              ms_column ? "from a Monte Carlo column per case" : "table");

  SlabRendererModelOptions converged = converged_renderer_model_options();
  SlabRendererModelOptions shader64;  // RenderQuality defaults, 1 m step floor
  shader64.jitter_samples = 16;

  std::vector<Row> rows;
  double mc_seconds = 0.0;
  for (double sun : suns) {
    for (double tau : taus) {
      Row r{tau, sun, {}, {}, {}, {}, {}};
      const SlabSpec slab = slab_from_optical_depth(tau, sun, d_um);
      SlabMcOptions o;
      // Cost per photon grows ~linearly with tau (collisions): ~6 CPU-s per case, so
      // ~3 CPU-min in all (1.5 min on 2 idle cores) at scale 1.
      o.photons = static_cast<std::uint64_t>(scale * 6.0e6 / (1.0 + tau)) + 1000;
      o.threads = threads;
      o.seed = seed;
      for (const ViewCase& v : kViews) o.views.push_back(v.v);
      r.mc = run_slab_monte_carlo(slab, o);
      mc_seconds += r.mc.seconds;
      MsSourceColumn column;
      if (ms_column) {
        MsSourceOptions mo;
        mo.photons = static_cast<std::uint64_t>(ms_scale * 2.0e6 / (1.0 + tau)) + 2000;
        mo.threads = threads;
        mo.seed = seed + 1;
        column = compute_ms_source_column(tau, std::cos(sun * std::numbers::pi / 180.0), jdd_params(d_um), mo);
        mc_seconds += column.seconds;
        converged.ms_source_column = &column;
        shader64.ms_source_column = &column;
      }
      for (const ViewCase& v : kViews) {
        r.model_top.push_back(slab_renderer_model_radiance(slab, v.v, true, converged).radiance);
        r.model_bottom.push_back(slab_renderer_model_radiance(slab, v.v, false, converged).radiance);
        r.model64_top.push_back(slab_renderer_model_radiance(slab, v.v, true, shader64).radiance);
        r.model64_bottom.push_back(slab_renderer_model_radiance(slab, v.v, false, shader64).radiance);
      }
      std::fprintf(stderr, "tau %g sun %g: %llu photons, %.1f collisions/photon, %.1f s\n", tau, sun,
                   static_cast<unsigned long long>(r.mc.photons), r.mc.mean_collisions, r.mc.seconds);
      rows.push_back(std::move(r));
    }
  }

  std::printf("\n### Fluxes (MC; fractions of the incident flux)\n\n");
  std::printf("| tau | sun | R ± se | T ± se | T diffuse | R + T |\n|---:|---:|---:|---:|---:|---:|\n");
  for (const Row& r : rows)
    std::printf("| %g | %g | %.4f ± %.4f | %.4f ± %.4f | %.4f | %.4f |\n", r.tau, r.sun, r.mc.reflected.mean,
                r.mc.reflected.std_error, r.mc.transmitted.mean, r.mc.transmitted.std_error,
                r.mc.transmitted_diffuse.mean, r.mc.reflected_plus_transmitted.mean);
  print_table(rows, true);
  print_table(rows, false);
  // One number per side for comparing light models: the geometric-mean factor between the
  // converged model and the MC, exp(mean |ln(model / MC)|), and the worst factor.
  for (bool top : {true, false}) {
    double sum = 0.0, worst = 0.0;
    int n = 0;
    for (const Row& r : rows)
      for (size_t k = 0; k < std::size(kViews); ++k) {
        const double mc = top ? r.mc.radiance_top[k].mean : r.mc.radiance_bottom[k].mean;
        const double m = top ? r.model_top[k] : r.model_bottom[k];
        if (!(mc > 0.0) || !(m > 0.0)) continue;
        const double e = std::fabs(std::log(m / mc));
        sum += e;
        worst = std::max(worst, e);
        ++n;
      }
    std::printf("\n%s: model/MC factor, geometric mean %.2f, worst %.2f (%d cases)\n",
                top ? "Reflected" : "Transmitted", std::exp(sum / std::max(n, 1)), std::exp(worst), n);
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("\nMonte Carlo %.0f s, total %.0f s (%d threads, scale %g, seed %llu).\n", mc_seconds, total,
              cloudsvc::resolve_threads(threads), scale, static_cast<unsigned long long>(seed));
  return 0;
}
