// What every pass that evaluates the cloud density and its lighting reads: the frame
// buffers (uniforms, counters), the cloud field (noise, weather keyframes, coverage
// pyramid) and the atmosphere lookups. A pass calls bind() before its dispatch, so no pass
// depends on what an earlier one left bound.
#pragma once

#include "renderer/atmosphere_luts.h"
#include "renderer/cloud_field_textures.h"
#include "renderer/dome_field.h"
#include "renderer/frame_buffers.h"

namespace cloudsvc {

struct CloudPassInputs {
  const FrameBuffers& frame;
  const CloudFieldTextures& field;
  const AtmosphereLuts& atmosphere;
  const DomeField* domes = nullptr;  // the cumulus dome fields, where the renderer draws them

  void bind() const {
    frame.bind();
    field.bind();
    atmosphere.bind_lookups();
    if (domes) domes->bind();
  }
};

}  // namespace cloudsvc
