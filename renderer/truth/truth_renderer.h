// The ground truth of a view (docs/ACCURACY.md): the scene of the model (the same density
// field, atmosphere, ground, sun and night sky as the CPU reference and the GPU renderer,
// scene_world.h) rendered by an unbiased volumetric path tracer with every order of
// scattering (path_tracer.h), in double precision, with each pixel's standard error.
//
// Per pixel: spp paths through uniformly random points of the pixel's footprint (the box
// filter of the reference's pixel_samples), each with one radiance estimate and one
// cloud-transmittance estimate; rgb = mean radiance, a = 1 - mean cloud transmittance (the
// cloud opacity), std_error = the standard error of the rgb mean (sample standard
// deviation / sqrt(spp)).
//
// Deterministic: pixel i draws from its own PCG32 stream (model::chunk_stream(seed, i)),
// so an image depends on (view, weather, settings.spp, settings.seed) only, not on the
// thread count.
#pragma once

#include "renderer/api/frame_image.h"
#include "renderer/api/view_request.h"
#include "renderer/reference/reference_inputs.h"
#include "renderer/truth/path_tracer.h"
#include "weather/cloud_layer.h"
#include "weather/wind_drift.h"

namespace cloudsvc::truth {

struct TruthSettings {
  int spp = 64;                  // paths per pixel, >= 2 (the standard error needs two)
  std::uint64_t seed = 1;
  int threads = 0;               // worker threads over pixels, 0 = all cores (common/parallel_for.h)
  TracerSettings tracer;
  reference::InputConfig inputs;  // the shared noise volumes and weather map (as the reference)
  bool honour_stratiform = true;  // the model's definition (reference::CloudField)
  bool noise_tiling = false;      // the noise volumes' stochastic tiling (RendererConfig::noise_tiling)
  // The layers' phase function (RendererConfig::cloud_phase; model/mie_phase_table.h)
  model::CloudPhaseModel cloud_phase = model::CloudPhaseModel::kFit;
};

struct TruthImage {
  FrameImage image;          // rgba + std_error; stats: render_ms, sun, cloud_pixels,
                             // density_evals_per_pixel (all paths of a pixel and the
                             // SunDepthCache's cells, per pixel), nonfinite_pixels
  TracerCounters counters;   // over all paths
  std::size_t sun_depth_cells = 0;       // cells of the SunDepthCache computed
  std::uint64_t sun_depth_evals = 0;     // medium evaluations spent on them
  int spp = 0;
  // Per pixel: 1 if one of its paths exceeded tracer.max_collisions. Such a pixel stops
  // there; its value is the mean of the paths completed before (biased low: the long
  // paths are missing) and must not be taken as the truth. Deep inside optically thick
  // clouds paths scatter 1e4-1e6 times (diffusion: the count grows with the square of the
  // optical depth), which a cap per path turns into a bounded cost per pixel.
  std::vector<std::uint8_t> incomplete;
  int incomplete_pixels = 0;
};

TruthImage render_truth(const ViewRequest& view, const weather::Weather& weather, const TruthSettings& settings = {},
                        const WindAnchor* wind_anchor = nullptr);

}  // namespace cloudsvc::truth
