// What every pass that evaluates the cloud density and its lighting reads: the frame
// buffers (uniforms, counters), the cloud field (noise, weather keyframes, coverage
// pyramid) and the atmosphere lookups. A pass calls bind() before its dispatch, so no pass
// depends on what an earlier one left bound.
#pragma once

#include "renderer/atmosphere_luts.h"
#include "renderer/cloud_field_textures.h"
#include "renderer/cloud_phase_texture.h"
#include "renderer/density_programs.h"
#include "renderer/dome_field.h"
#include "renderer/frame_buffers.h"
#include "renderer/ground_albedo_texture.h"
#include "renderer/ms_source_textures.h"

namespace cloudsvc {

struct CloudPassInputs {
  const FrameBuffers& frame;
  const CloudFieldTextures& field;
  const AtmosphereLuts& atmosphere;
  // The multiple-scattering source tables (renderer/ms_source_textures.h).
  const MsSourceTextures& ms_source;
  // The ground's albedo where tiles set it (renderer/ground_albedo_texture.h).
  const GroundAlbedoTexture& ground_albedo;
  // The cumulus dome fields, where this frame draws dome layers; the passes then run their
  // programs' dome variant (renderer/density_programs.h).
  const DomeField* domes = nullptr;
  // The quality's marches leave llvmpipe's loop budget for the dome sub-grid's loop
  // (density_loops_fit, renderer/density_programs.h).
  bool density_loops = false;
  // The layers' Mie phase tables, where the renderer scatters with them
  // (RendererConfig::cloud_phase; renderer/cloud_phase_texture.h).
  const CloudPhaseTexture* phase = nullptr;

  // Binds the density program variant for this frame (before bind()).
  void use(const DensityPrograms& programs) const {
    programs.use(domes != nullptr, density_loops, field.noise_tiling());
  }

  void bind() const {
    frame.bind();
    field.bind();
    atmosphere.bind_lookups();
    ms_source.bind();
    ground_albedo.bind();
    if (domes) domes->bind();
    if (phase) phase->bind();
  }
};

}  // namespace cloudsvc
