// The layers' tabulated Mie phase functions on the GPU (RendererConfig::cloud_phase = kMie;
// renderer/model/mie_phase_table.h): one RGBA32F row of model::kPhaseTableSamples texels
// per layer slot (rgb = 680 / 550 / 440 nm), read by tabulated_phase in
// shaders/phase_function.glsl with linear filtering along the angle.
//
// A row follows its layer's droplet diameter. A new diameter's table takes ~0.7 s at 10 um
// and ~14 s at 50 um on 2 cores to compute (once per process, on a thread of its own,
// model::mie_phase_table_future). With `wait` the update waits for it (a rendered file or
// test shows the Mie phase from the first frame); without, the row holds the
// Jendersie-d'Eon fit at the same angles until the table is ready, and the frames go on
// (the service: a weather change never stalls the render thread). Needs a current GL 4.5
// context.
#pragma once

#include <array>

#include "renderer/frame_context.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/gpu_interface.h"
#include "renderer/model/mie_phase_table.h"

namespace cloudsvc {

class CloudPhaseTexture {
 public:
  explicit CloudPhaseTexture(bool wait);
  // Brings the rows of the frame's layers up to date (see above).
  void update(const FrameContext& frame);
  // Binds the texture at gpu::tex::CLOUD_PHASE.
  void bind() const;
  // Rows that hold the fit while their layer's Mie table is computed.
  int pending_rows() const;
  static constexpr std::size_t gpu_bytes() { return 16u * model::kPhaseTableSamples * gpu::kMaxLayers; }

 private:
  struct Row {
    double diameter_um = 0.0;  // 0: not written
    model::PhaseTableFuture table;
    bool holds_mie = false;
  };
  void upload(int row, const model::PhaseTable& table);
  void upload_fit(int row, double diameter_um);

  bool wait_;
  gl::Texture texture_;
  std::array<Row, gpu::kMaxLayers> rows_{};
  int layers_ = 0;  // layers of the last frame
};

}  // namespace cloudsvc
