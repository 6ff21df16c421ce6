#include "renderer/cloud_phase_texture.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

#include "renderer/model/phase_function.h"

namespace cloudsvc {

CloudPhaseTexture::CloudPhaseTexture(bool wait)
    : wait_(wait),
      texture_(gl::make_texture_2d(GL_RGBA32F, model::kPhaseTableSamples, gpu::kMaxLayers, GL_CLAMP_TO_EDGE,
                                   GL_CLAMP_TO_EDGE)) {}

void CloudPhaseTexture::upload(int row, const model::PhaseTable& table) {
  std::vector<float> texels(4 * static_cast<std::size_t>(model::kPhaseTableSamples), 0.0f);
  for (int k = 0; k < model::kPhaseTableSamples; ++k)
    for (int c = 0; c < 3; ++c)
      texels[4 * static_cast<std::size_t>(k) + c] = static_cast<float>(table.phase[static_cast<std::size_t>(k)][c]);
  glTextureSubImage2D(texture_.id(), 0, 0, row, model::kPhaseTableSamples, 1, GL_RGBA, GL_FLOAT, texels.data());
}

void CloudPhaseTexture::upload_fit(int row, double diameter_um) {
  const model::JdDParams p = model::jdd_params(diameter_um);
  model::PhaseTable fit;
  fit.phase.resize(model::kPhaseTableSamples);
  for (int k = 0; k < model::kPhaseTableSamples; ++k)
    fit.phase[static_cast<std::size_t>(k)] =
        glm::dvec3(model::jdd_phase(std::cos(model::phase_table_angle_deg(k) * M_PI / 180.0), p));
  upload(row, fit);
}

void CloudPhaseTexture::update(const FrameContext& frame) {
  layers_ = std::min(frame.layer_count, gpu::kMaxLayers);
  for (int i = 0; i < frame.layer_count && i < gpu::kMaxLayers; ++i) {
    Row& r = rows_[static_cast<std::size_t>(i)];
    const double d = frame.layers[static_cast<std::size_t>(i)].layer.droplet_diameter_um;
    if (r.diameter_um != d) {
      r.diameter_um = d;
      r.table = model::mie_phase_table_future(d);
      r.holds_mie = false;
      const bool ready = wait_ || r.table.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
      if (!ready) upload_fit(i, d);
    }
    if (!r.holds_mie && (wait_ || r.table.wait_for(std::chrono::seconds(0)) == std::future_status::ready)) {
      upload(i, *r.table.get());
      r.holds_mie = true;
    }
  }
}

int CloudPhaseTexture::pending_rows() const {
  int n = 0;
  for (int i = 0; i < layers_; ++i) n += rows_[static_cast<std::size_t>(i)].holds_mie ? 0 : 1;
  return n;
}

void CloudPhaseTexture::bind() const { glBindTextureUnit(gpu::tex::CLOUD_PHASE, texture_.id()); }

}  // namespace cloudsvc
