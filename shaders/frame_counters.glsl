// Counters of a frame (storage buffer SSBO_FRAME_COUNTERS), read back after the frame
// (CloudRenderer::render, FrameStats). Zeroed before the first pass of each frame.
layout(std430, binding = SSBO_FRAME_COUNTERS) buffer FrameCounters {
  uint density_evals;     // cloud density evaluations of every pass (when counted)
  uint nonfinite_pixels;  // pixels the composite had to clamp (NaN, Inf, negative)
  uint cloud_pixels;      // pixels with cloud opacity > CLOUD_PIXEL_OPACITY
} counters;
