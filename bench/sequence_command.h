// `cloudbench --sequence`: temporal reuse on a moving camera (issue 5): a camera flying at
// 250 m/s at 30 frames/s, turning at 3 deg/s, through and past clouds. For every frame and
// configuration, the error against a converged march of the same frame (GPU, 256 log
// steps, 12 light steps, no reuse: the CPU reference would take hours per sequence; the
// GPU path itself is held to the CPU reference by cloudbench and the accuracy tests),
// rendered at --ref-samples times the size and box-filtered down: the pixel's footprint
// sampled by n x n stratified rays, as cloudbench's reference is.
// The first frame carries the teleport flag, as a replay's first pose does.
// Writes DIR/sequence.csv and DIR/sequence.md; prints the summary.
//
//   build/bin/cloudbench --sequence [--size 160x90] [--frames 60] [--ref-samples 2] [--out bench-out]
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "geodesy/utc_time.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/image_metrics.h"
#include "tests/fixtures/flight_sequence.h"
#include "weather/presets.h"

namespace cloudsvc::sequence_command {

struct Flight {
  const char* name;
  const char* preset;
  double alt_m, heading_deg, pitch_deg;
};

inline std::vector<Flight> flights() {
  return {{"through broken cumulus (1800 m, in and out of cloud)", "broken-cumulus", 1800.0, 250.0, 0.0},
          {"past scattered cumulus (1500 m, looking down 5 deg)", "scattered-cumulus", 1500.0, 250.0, -5.0},
          {"over a stratocumulus deck (2500 m)", "stratocumulus-deck", 2500.0, 90.0, -3.0}};
}

struct Summary {
  std::string flight, config;
  double mean_psnr = 0, worst_psnr = INFINITY, mean_ms = 0, first_psnr = 0, mean_rmse = 0;
  // mean GPU ms per pass over frames 1.. (FrameStats): view LUTs, shadow map, march, resolve, composite
  double luts_ms = 0, shadow_ms = 0, march_ms = 0, resolve_ms = 0, composite_ms = 0;
};

inline int run(int argc, char** argv) {
  CLI::App app{"Temporal reuse on a flying camera (cloudbench --sequence)"};
  std::string size = "160x90", out = "bench-out";
  int frames = 60;
  app.add_option("--size", size, "frame size WxH");
  app.add_option("--frames", frames, "frames per flight (30 per second)")->check(CLI::Range(2, 10000));
  app.add_option("--out", out, "output directory");
  int ref_samples = 2;
  app.add_option("--ref-samples", ref_samples, "reference rays per pixel along each axis (1: the pixel centre)")
      ->check(CLI::Range(1, 4));
  CLI11_PARSE(app, argc, argv);
  int w = 0, h = 0;
  if (!bench::parse_frame_size(size, w, h)) {
    std::fprintf(stderr, "cloudbench --sequence: --size expects WxH\n");
    return 2;
  }
  std::filesystem::create_directories(out);
  gl::EglContext context;
  RenderQuality converged;
  converged.primary_steps = 256;
  converged.light_steps = 12;
  RenderQuality full = *quality_preset("default");
  full.temporal_reuse = false;
  full.footprint_jitter = false;  // one sample per frame: the pixel centre, as the naive march
  const std::vector<std::pair<std::string, RenderQuality>> configs = {
      {"naive", *quality_preset("naive")}, {"default without temporal reuse (pixel centre)", full}, {"default", *quality_preset("default")},
      {"high (1/4 px per frame)", *quality_preset("high")}};
  std::ofstream csv(std::filesystem::path(out) / "sequence.csv");
  csv << "flight,config,frame,psnr_db,rmse,render_ms,marched_fraction,history_used\n";
  std::vector<Summary> summaries;
  for (const Flight& fl : flights()) {
    fixtures::FlightSequence s;
    s.start.position = {47.45, 8.56, fl.alt_m};
    s.start.attitude = {fl.heading_deg, fl.pitch_deg, 0.0};
    s.start.unix_time_s = *geo::parse_utc_iso8601("2026-06-21T11:30:00Z");
    s.start.width = w;
    s.start.height = h;
    s.start.reset_history = true;
    s.frames = frames;
    const std::vector<ViewRequest> views = fixtures::flight_views(s);
    CloudRenderer ref_renderer;
    ref_renderer.set_weather(*weather::preset(fl.preset));
    std::vector<FrameImage> refs;
    for (ViewRequest v : views) {
      v.reset_history = true;
      v.width = w * ref_samples;
      v.height = h * ref_samples;
      refs.push_back(reference::box_downsample(ref_renderer.render(v, converged), ref_samples));
    }
    for (const auto& [name, q] : configs) {
      CloudRenderer r;
      r.set_weather(*weather::preset(fl.preset));
      r.render(views[0], q);  // shader JIT and weather upload outside the measurement
      Summary sum{fl.name, name};
      for (size_t i = 0; i < views.size(); ++i) {
        const FrameImage img = r.render(views[i], q);
        const reference::ImageDifference d = reference::compare_images(img, refs[i]);
        csv << '"' << fl.name << "\",\"" << name << "\"," << i << ',' << d.psnr_db << ',' << d.rmse << ','
            << img.stats.render_ms << ',' << img.stats.marched_fraction << ',' << img.stats.history_used << '\n';
        sum.mean_psnr += d.psnr_db / static_cast<double>(views.size());
        sum.mean_rmse += d.rmse / static_cast<double>(views.size());
        sum.worst_psnr = std::min(sum.worst_psnr, d.psnr_db);
        if (i > 0) {
          const double k = 1.0 / static_cast<double>(views.size() - 1);
          sum.mean_ms += img.stats.render_ms * k;
          sum.luts_ms += img.stats.luts_ms * k;
          sum.shadow_ms += img.stats.shadow_map_ms * k;
          sum.march_ms += img.stats.march_ms * k;
          sum.resolve_ms += img.stats.resolve_ms * k;
          sum.composite_ms += img.stats.composite_ms * k;
        }
        if (i == 0) sum.first_psnr = d.psnr_db;
      }
      std::printf("%-52s %-32s PSNR mean %.2f worst %.2f first %.2f dB, %.1f ms/frame (LUTs %.1f, shadow map %.1f, "
                  "march %.1f, resolve %.1f, composite %.1f)\n",
                  fl.name, name.c_str(), sum.mean_psnr, sum.worst_psnr, sum.first_psnr, sum.mean_ms, sum.luts_ms,
                  sum.shadow_ms, sum.march_ms, sum.resolve_ms, sum.composite_ms);
      std::fflush(stdout);
      summaries.push_back(sum);
    }
  }
  std::ostringstream md;
  md << "# cloudbench --sequence\n\nA camera flying at 250 m/s, 30 frames/s, turning at 3 deg/s, " << frames
     << " frames at " << w << "x" << h
     << " per flight. Error per frame on linear radiance against a converged march of the same frame (256 log "
        "steps, 12 light steps, no reuse) at " << ref_samples << "x the size, box-filtered to the pixel footprint. Frame 0 carries the teleport flag. ms/frame: median-free mean of "
        "frames 1.., llvmpipe; the per-pass columns are the mean GPU ms of each pass.\n\n| flight | config | PSNR mean dB | PSNR worst dB | PSNR frame 0 dB | RMSE mean | ms/frame | LUTs | shadow map | march | resolve | composite |\n"
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  char b[512];
  for (const Summary& s : summaries) {
    std::snprintf(b, sizeof b, "| %s | %s | %.2f | %.2f | %.2f | %.3e | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n",
                  s.flight.c_str(), s.config.c_str(), s.mean_psnr, s.worst_psnr, s.first_psnr, s.mean_rmse, s.mean_ms,
                  s.luts_ms, s.shadow_ms, s.march_ms, s.resolve_ms, s.composite_ms);
    md << b;
  }
  std::ofstream(std::filesystem::path(out) / "sequence.md") << md.str();
  return 0;
}

}  // namespace cloudsvc::sequence_command
