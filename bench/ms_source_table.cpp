// ms_source_table: generates the diffuse multiple-scattering source table of
// renderer/model/ms_source_table.h by Monte Carlo (one column per slab optical depth and
// sun zenith angle) and writes it in the embedded format. Prints each column's cost and
// its noise: the standard error relative to the value, over the nodes that matter (value
// at least 5 % of the column's largest).
//
//   build/bin/ms_source_table --out renderer/model/data/ms_source_table.bin [--scale 1] [--seed 1]
//   build/bin/ms_source_table --diffuse --scale 4 --out renderer/model/data/ms_diffuse_incidence_table.bin
//
// --diffuse: the source of diffuse (Lambertian) light entering through the top, one column
// per optical depth (MsSourceOptions::diffuse_incidence; ~4 min at --scale 4 on 2 cores).
//
// Deterministic for a seed (fixed Monte Carlo chunks), whatever the thread count.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "common/parallel_for.h"
#include "renderer/model/ms_source_table.h"
#include "renderer/model/phase_function.h"

int main(int argc, char** argv) {
  using namespace cloudsvc::model;
  CLI::App app{"Monte Carlo multiple-scattering source table of the cloud light model (renderer/model/ms_source_table.h)"};
  std::string out;
  double scale = 1.0;
  std::uint64_t seed = 1;
  int threads = cloudsvc::kAllThreads;
  app.add_option("--out", out, "output file (renderer/model/data/ms_source_table.bin)")->required();
  app.add_option("--scale", scale, "photon count multiplier (1: ~10 min on 2 cores)")->check(CLI::Range(0.001, 1000.0));
  app.add_option("--seed", seed, "random seed");
  app.add_option("--threads", threads, "worker threads (0: all cores; the table does not depend on it)")
      ->check(CLI::Range(0, 256));
  bool diffuse = false;
  app.add_flag("--diffuse", diffuse,
               "the table of diffuse light entering through the top "
               "(renderer/model/data/ms_diffuse_incidence_table.bin, generated with --scale 4; one column per optical "
               "depth) instead of the sun's");
  CLI11_PARSE(app, argc, argv);

  const auto t0 = std::chrono::steady_clock::now();
  const MsSourceTableBuild build =
      build_ms_source_table(MsSourceTableShape{}, jdd_params(kMsTableDropletUm), scale, seed, threads, diffuse);
  std::printf("| tau | sun zenith | photons | collisions/photon | s | median rel. se | 90th pct rel. se |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|\n");
  std::vector<double> all;
  for (const MsSourceColumn& c : build.columns) {
    const double peak = *std::max_element(c.j_over_mu.begin(), c.j_over_mu.end());
    std::vector<double> rel;
    for (std::size_t i = 0; i < c.j_over_mu.size(); ++i)
      if (c.j_over_mu[i] >= 0.05 * peak && peak > 0.0) rel.push_back(c.std_error[i] / c.j_over_mu[i]);
    std::sort(rel.begin(), rel.end());
    all.insert(all.end(), rel.begin(), rel.end());
    const double med = rel.empty() ? 0.0 : rel[rel.size() / 2];
    const double p90 = rel.empty() ? 0.0 : rel[rel.size() * 9 / 10];
    std::printf("| %g | %.1f | %llu | %.1f | %.1f | %.3f | %.3f |\n", c.tau, std::acos(c.mu_s) * 180.0 / M_PI,
                static_cast<unsigned long long>(c.photons), c.mean_collisions, c.seconds, med, p90);
    if (c.lost_photons > 0)
      std::fprintf(stderr, "warning: tau %g: %llu photons lost\n", c.tau, static_cast<unsigned long long>(c.lost_photons));
  }
  std::sort(all.begin(), all.end());
  const auto bytes = build.table.serialise();
  std::ofstream f(out, std::ios::binary);
  f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!f) {
    std::fprintf(stderr, "ms_source_table: cannot write %s\n", out.c_str());
    return 2;
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("\nAll nodes >= 5 %% of their column's peak: relative standard error median %.3f, 90th percentile "
              "%.3f, largest %.3f. %zu bytes to %s in %.0f s (%d threads, scale %g, seed %llu).\n",
              all.empty() ? 0.0 : all[all.size() / 2], all.empty() ? 0.0 : all[all.size() * 9 / 10],
              all.empty() ? 0.0 : all.back(), bytes.size(), out.c_str(), total, cloudsvc::resolve_threads(threads),
              scale, static_cast<unsigned long long>(seed));
  return 0;
}
