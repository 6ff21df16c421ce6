// How carefully to draw: the march settings a quality preset (renderer/quality_presets.h)
// fills in. Plain data shared by the GPU renderer and the CPU reference (no GL).
#pragma once

namespace cloudsvc {

// Quality knobs of the ray march. The march code is the same for every preset; presets
// only change these numbers.
struct RenderQuality {
  int primary_steps = 64;       // steps along the view ray through all layer intervals
  int light_steps = 6;          // steps of the secondary march towards the sun
  int ground_shadow_steps = 8;  // steps per layer of the ground-to-sun shadow march
  // The diffuse light's optical depths above and below each point from its own vertical
  // column (the independent column approximation, Cahalan et al. 1994): the column volume
  // (renderer/ground_shadow_map.h, shaders/column_volume.glsl), built with the ground shadow
  // map by integrating each of its columns from the layer's base to its top (base shape,
  // the quadrature of shaders/column_quadrature.glsl) in this many steps, at least one per
  // altitude level of the volume. 0: the depths of a homogeneous layer of the map's coverage instead
  // (the layer's nominal extinction times the distances to its top and base).
  int column_steps = 0;
  // Where the column depths come from: the column volume (built with the ground shadow map,
  // free between rebuilds, but its texels grow with distance: hundreds of metres a few km
  // away, kilometres from 30 km up), or, if false or without ground_shadow_map, marched from
  // each lit sample along its own vertical in column_steps steps as the reference does (N
  // base-shape evaluations per lit sample; at any distance the point's own column;
  // docs/RENDERING.md "Column volume").
  bool column_volume = true;
  // The sun's diffuse source from a slab tilted towards the sun (side illumination of 3-D
  // clouds; tilted_sun_slab in shaders/cloud_lighting.glsl, docs/RENDERING.md "Light"), its
  // depth from the light march; false: the horizontal slab of the column. Only with
  // column_steps > 0: the tilt compares the sun's depth with the point's own column, and a
  // homogeneous layer's depths are not those of the cloud the light march crosses. Off in
  // every preset (docs/ACCURACY.md section 0 has the measurements).
  bool sun_slab_tilt = false;
  // Primary steps are uniform in ln(1 + t / t_ref): step length grows with distance t
  // like the pixel footprint. 0 = uniform steps in t (the naive march).
  double step_growth_ref_m = 1000.0;
  // Ground cloud shadows from the ground shadow map (renderer/ground_shadow_map.h: built
  // once, reused while the sun, weather and camera region hold) or marched per ground
  // pixel every frame (exact, ground_shadow_steps per layer per pixel).
  bool ground_shadow_map = true;
  // Self-shadowing from the light volume (renderer/ground_shadow_map.h: each layer's optical
  // depth towards the sun on a 128 x 128 x 16 grid per layer, built with the ground shadow
  // map and light_steps light steps) instead of a light march from every sample. Needs
  // ground_shadow_map; ignored without it.
  bool light_volume = false;
  // Skips (issue 5; each is switchable and measured by bench/cloudbench --skips):
  // In empty air, probe with steps this many times longer and step back where the span
  // since the last sample may hold cloud (a bound: the image is that of 1, every step
  // evaluated in full). 4: fewest evaluations on the core scenes (2: 12.5, 3: 12.0,
  // 4: 11.9, 8: 12.3 per pixel per frame at the default preset, cloudbench --cost).
  int long_step_factor = 4;
  // Coverage max-pyramid (renderer/coverage_pyramid.h): runs of primary steps whose map
  // footprint the pyramid clears for their layer are skipped without a density evaluation.
  bool coverage_pyramid = true;
  // Light marches stop once the sun term is below e^-cutoff of its unshadowed value,
  // whatever lies beyond: the peak beam decays as e^(-w_D tau), so past an optical depth of
  // cutoff / w_D towards the sun (26.8 for 12 and the smallest w_D; a cut-off of 8 changed
  // the sunset deck's image by 0.3 %, tests/render_light_cutoff_test.cpp). 0 = march every
  // light step.
  double light_march_cutoff = 12.0;
  // Level of detail by the pixel footprint: detail noise replaced by its mean, and fewer
  // light steps, once a pixel spans several noise texels.
  bool level_of_detail = false;
  // Clouds drawn into a buffer of 1/divisor of the frame in each axis, upsampled with
  // depth-aware weights (1 = full resolution).
  int cloud_resolution_divisor = 1;
  // Temporal reuse: each frame marches one cloud pixel in stride x stride (1 = all of
  // them, 2 = 1/4, 4 = 1/16) and reprojects the rest from the previous frame; fresh
  // samples of a still camera are averaged with their history. Off: every frame is
  // marched in full and nothing is kept.
  bool temporal_reuse = false;
  int temporal_stride = 1;
  // While the nearest clouds move by more than this many frame pixels per frame
  // (cloud_motion_px, renderer/temporal_reprojection.h), march 1/4 of the pixels instead
  // of 1/16: a fast, close pass would otherwise show each pixel's history resampled and
  // re-lit for 16 frames (docs/PERFORMANCE.md, "A moving camera"). 0 = never.
  double fast_motion_px = 0.0;
  // Pixel footprint sampling: each frame's march ray goes through a different point of its
  // cloud pixel (a per-pixel rotated Kronecker sequence over frames) instead of the centre,
  // so that temporal accumulation integrates the pixel's footprint (antialiasing) and the
  // frame-to-frame noise of a pixel shows how much its value depends on where in the pixel
  // it is sampled. Off: the centre, every frame.
  bool footprint_jitter = false;
  double history_blend_min = 0.2;  // least weight of a fresh sample against its history
  bool neighbourhood_clamp = true;  // limit moved history to the range of fresh neighbours
  bool count_density_evaluations = true;
};

}  // namespace cloudsvc
