// Spread of the ground truth's per-path radiance estimates in a homogeneous slab, without
// sun-guided copies, with copies at any depth (at most 64 per camera path) and with the
// default copies (where the sun is less than TracerSettings::guide_depth deep) (docs/TRUTH.md, "The estimator"): mean, standard deviation,
// quantiles, the largest paths and the work per path, so that the variance reduction per
// unit of work can be read off; and the slab Monte Carlo's answer for the same view
// (renderer/model/slab_monte_carlo.h, 10^6 photons).
//
// Usage: truth_path_spread [--tau T (4)] [--sun-zenith DEG (60)] [--paths N (100000)]
//                          [--guide-cell M (TracerSettings::guide_cell_m)]
// The camera is 500 m below the slab's base looking straight up; sun irradiance 1;
// droplet diameter 14 um; black ground; no air.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "renderer/model/scene_constants.h"
#include "renderer/model/slab_monte_carlo.h"
#include "renderer/truth/path_tracer.h"

namespace {

using namespace cloudsvc;

struct Slab final : truth::TruthMedium {
  double base = 0.0, top = 0.0, sigma = 0.0;
  void at(const glm::dvec3&, double alt, truth::MediumPoint& out) const override {
    if (alt > base && alt < top) out.cloud[0] = sigma;
  }
};

void report(const char* label, const truth::TruthWorld& world, const truth::TracerSettings& settings, long paths) {
  truth::TracerCounters counters;
  model::Pcg32 rng = model::chunk_stream(1, 0);
  const truth::SunDepthCache sun_depth = truth::make_sun_depth_cache(world, settings);
  truth::PathTracer tracer(world, settings, sun_depth, rng, counters);
  const glm::dvec3 camera(0.0, 0.0, world.radius_m + 500.0), up(0.0, 0.0, 1.0);
  std::vector<double> v(static_cast<std::size_t>(paths));
  double sum = 0.0, sum2 = 0.0;
  for (double& x : v) {
    x = tracer.radiance(camera, up).g;
    sum += x;
    sum2 += x * x;
  }
  const double n = static_cast<double>(paths), mean = sum / n;
  const double sd = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
  std::sort(v.begin(), v.end());
  const double work = static_cast<double>(counters.density_evals + sun_depth.density_evals()) / n;
  std::printf("%-16s mean %.5f +- %.5f  s.d. per path %.3f  p50 %.4f p99 %.3f p99.9 %.3f  largest %.1f %.1f %.1f"
              "  evaluations/path %.1f  variance x work %.3f\n",
              label, mean, sd / std::sqrt(n), sd, v[v.size() / 2], v[v.size() * 99 / 100], v[v.size() * 999 / 1000],
              v[v.size() - 1], v[v.size() - 2], v[v.size() - 3], work, sd * sd * work);
}

}  // namespace

int main(int argc, char** argv) {
  double tau = 4.0, sun_zenith = 60.0, guide_cell = truth::TracerSettings{}.guide_cell_m;
  long paths = 100000;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--tau" && has_value) tau = std::atof(argv[++i]);
    else if (a == "--sun-zenith" && has_value) sun_zenith = std::atof(argv[++i]);
    else if (a == "--paths" && has_value) paths = std::atol(argv[++i]);
    else if (a == "--guide-cell" && has_value) guide_cell = std::atof(argv[++i]);
    else {
      std::fprintf(stderr, "usage: truth_path_spread [--tau T] [--sun-zenith DEG] [--paths N] [--guide-cell M]\n");
      return a == "--help" ? 0 : 2;
    }
  }
  if (!(tau > 0.0) || !(sun_zenith >= 0.0 && sun_zenith < 90.0) || paths < 2 || !(guide_cell > 0.0)) {
    std::fprintf(stderr, "truth_path_spread: need tau > 0, sun zenith in [0, 90), paths >= 2, guide cell > 0\n");
    return 2;
  }
  const model::SlabSpec spec = model::slab_from_optical_depth(tau, sun_zenith);
  Slab slab;
  slab.base = 1000.0;
  slab.top = 1000.0 + spec.thickness_m;
  slab.sigma = spec.sigma_t_per_m;
  truth::TruthWorld w;
  w.radius_m = 1e9;  // flat enough
  w.top_alt_m = slab.top + 1000.0;
  w.band_edges = {0.0, slab.base, slab.top, w.top_alt_m};
  w.band_majorant = {0.0, slab.sigma * (1.0 + 1e-9), 0.0};
  w.band_air_majorant = {0.0, 0.0, 0.0};
  w.sun = model::sun_direction(sun_zenith);
  w.sun_irradiance = glm::dvec3(1.0);
  w.sun_angular_radius_rad = model::kSunAngularRadiusDeg * std::numbers::pi / 180.0;
  w.cloud_phase[0] = model::jdd_params(spec.droplet_diameter_um);
  w.medium = &slab;
  std::printf("slab optical depth %.2f, sun zenith %.1f deg, %ld paths, view up from below\n", tau, sun_zenith, paths);
  {
    model::SlabMcOptions o;  // the independent answer: photons traced from the sun
    o.photons = 1000000;
    o.views = {{0.0, 0.0}};
    const model::SlabMcResult mc = model::run_slab_monte_carlo(spec, o);
    std::printf("slab Monte Carlo (%llu photons): %.5f +- %.5f\n", static_cast<unsigned long long>(o.photons),
                mc.radiance_bottom[0].mean, mc.radiance_bottom[0].std_error);
  }
  truth::TracerSettings gated;
  gated.guide_cell_m = guide_cell;
  truth::TracerSettings plain = gated;
  plain.sun_guiding = 0.0;
  report("no copies", w, plain, paths);
  truth::TracerSettings everywhere = gated;  // the estimator before the gate: copies at any depth, at most 64
  everywhere.guide_depth = std::numeric_limits<double>::infinity();
  everywhere.max_copies = 64;
  report("copies anywhere", w, everywhere, paths);
  char label[64];
  std::snprintf(label, sizeof label, "copies, depth<%g", gated.guide_depth);
  report(label, w, gated, paths);
  return 0;
}
