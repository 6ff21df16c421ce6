// Whether any ray of the frame can meet a cloud layer (issue 5: "a frame above a solid deck
// looking up costs no cloud march at all"). Exact for the view frustum: the range of the
// rays' zenith cosines mu over the image rectangle is found from its four edges (each a
// great-circle arc: a straight image line is a plane through the eye) and the zenith or
// nadir when inside; a layer is in view when some mu in that range meets its shell:
//   camera at or above the layer top: mu below the top sphere's tangent cosine;
//   camera inside the layer: always;
//   camera below the base: some ray does not hit the ground first (mu above the ground's
//   tangent cosine).
// Conservative: the march reach and the layer's coverage are not used (a layer beyond reach
// is still "in view"), so skipping the march when this is false changes no pixel.
#pragma once

#include <glm/glm.hpp>

#include "renderer/frame_context.h"

namespace cloudsvc {

struct MuRange {
  double min = -1.0, max = 1.0;
};

// Range of dir.z over the rays dir = normalize(f + x tx r + y ty u), x, y in [-1, 1] (local
// ENU axes; f, r, u the camera's forward, right and up unit vectors; tx, ty the tangents of
// the half fields of view).
MuRange frustum_mu_range(const glm::dvec3& f, const glm::dvec3& r, const glm::dvec3& u, double tx, double ty);

// What the rays of the frame reach.
struct FrameRays {
  // some ray meets a layer with coverage > 0 (culled layers do not count: the march skips
  // them anyway)
  bool meets_a_layer = false;
  // ... one of them under another drawn layer, whose light the march reads from the ground
  // shadow map (shaders/layers_above.glsl)
  bool meets_a_layer_under_another = false;
  // some ray hits the ground sphere (whose pixels need the ground shadow map); false, for
  // example, for a camera looking up
  bool sees_ground = false;
};
FrameRays classify_frame_rays(const FrameContext& frame);

}  // namespace cloudsvc
