// Counters of a frame (storage buffer SSBO_FRAME_COUNTERS), read back after the frame
// (CloudRenderer::render, FrameStats). Zeroed before the first pass of each frame.
layout(std430, binding = SSBO_FRAME_COUNTERS) buffer FrameCounters {
  uint density_evals;            // cloud density evaluations of every pass (when counted)
  uint nonfinite_pixels;         // pixels the composite had to clamp (NaN, Inf, negative)
  uint cloud_pixels;             // pixels with cloud opacity > CLOUD_PIXEL_OPACITY
  uint loop_capped_invocations;  // invocations whose loops the driver cut short (below)
} counters;

// Mesa's llvmpipe ends the loops of an invocation once they have run 65535 iterations in
// all (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS, one budget shared by every loop of the
// shader and by the SIMD lanes run together); every loop after that runs its body once,
// without any error. A pass calls this as its last step: its loop of two iterations runs
// once only when the budget is spent, and the invocation is then counted (FrameStats::
// loop_capped_invocations; any count means the image is wrong, not just slow). The bound
// reads the counter itself: below 2^31, so the shift gives 0, which the compiler cannot
// know (a constant trip count would be unrolled into no loop at all).
void count_if_loops_capped() {
  int n = 2 + int(counters.loop_capped_invocations >> 31);
  int runs = 0;
  for (int i = 0; i < n; ++i) ++runs;
  if (runs < n) atomicAdd(counters.loop_capped_invocations, 1u);
}
