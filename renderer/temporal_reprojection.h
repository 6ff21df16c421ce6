// Temporal reuse of the cloud buffer (shaders/cloud_resolve.comp): which pixels a frame
// marches, whether the previous frame's buffer may be reused, and the transforms that
// carry a point of the current camera's local frame to where the same cloud (or ground)
// was seen from the previous camera. Computed in double on the CPU; no GL here.
#pragma once

#include <algorithm>

#include <glm/glm.hpp>

#include "renderer/api/frame_image.h"
#include "renderer/frame_context.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"
#include "renderer/temporal_uniforms.h"
#include "weather/wind_drift.h"
#include "weather/cloud_layer.h"

namespace cloudsvc {

// Offset (x, y) in [0, stride)^2 of the cloud pixels marched by frame frame_index: a
// 2x2 or 4x4 ordered-dither sequence, so that consecutive frames are spread evenly and
// every pixel is marched once per stride^2 frames. Stride 1: (0, 0).
glm::ivec2 fresh_pixel_offset(int stride, std::uint32_t frame_index);

// Whether the previous frame's cloud buffer can be reprojected into this one: not after
// a teleport/reset (ViewRequest::reset_history), a change of size, field of view or
// march settings, time running backwards or more than kMaxHistoryGapS between frames (a
// slide show, e.g. a replay at 0.2 frames/s: each frame stands alone and is marched in
// full), or the camera jumping more than kMaxHistoryJumpM or turning more than
// kMaxHistoryTurnDeg in one frame (an unannounced teleport or a snap view change: too
// little left to reuse).
constexpr double kMaxHistoryGapS = 0.5;
constexpr double kMaxHistoryJumpM = 5000.0;
constexpr double kMaxHistoryTurnDeg = 10.0;
bool history_usable(const ViewRequest& prev, const RenderQuality& prev_quality, const ViewRequest& cur,
                    const RenderQuality& cur_quality);

// A camera that has not moved (under kStillCameraM) or turned (under kStillCameraDeg on
// each axis) since the previous frame: only then are fresh samples averaged with their
// history (the jitter noise falls over frames). A moving camera's history is resampled
// and its lighting may be changing, so a fresh sample replaces it.
constexpr double kStillCameraM = 0.5;
constexpr double kStillCameraDeg = 1e-3;
bool camera_still(const ViewRequest& prev, const ViewRequest& cur);

// Which footprint sample a cloud pixel marched this frame takes (shaders/cloud_march.comp,
// with RenderQuality::footprint_jitter): 0 is the pixel's centre, n >= 1 the n-th point of
// its rotated R2 sequence. With temporal reuse, from still_frames: consecutive frames with
// a still camera, this one included (0: history reset or a moving camera, whose fresh
// samples replace their history, so the centre, as the full march, is the best single
// sample). In a still run every pixel is marched once per stride^2 frames, so frame s of it
// gives its pixels their ceil(s / stride^2)-th sample after the centre: the first two
// samples of a pixel are its centre and one point of the footprint, never two random points
// (whose average errs more at an edge than the centre alone; docs/ACCURACY.md). Without
// temporal reuse the renderer accumulates nothing; a caller that averages frames itself
// (the stability sweep, an offline accumulation) gets point frame_index mod 65536.
int footprint_sample_index(int still_frames, int stride);
int footprint_sample_index(bool temporal_reuse, std::uint32_t frame_index, int still_frames, int stride);

// p_prev = M p_cur for points of layer li's cloud field (camera motion and the layer's
// wind between the two times), and for the ground at index kGroundTransform. Layers
// beyond the weather's get the ground transform.
struct Reprojection {
  glm::dmat4 transform[gpu::kMaxLayers + 1];
  geo::BodyAxes prev_axes;  // previous camera axes in its own local frame
  double cloud_motion_px = 0.0;  // cloud_motion_px() of the two frames
};

// How far the nearest clouds move across the image between two frames, in frame pixels
// (an upper estimate): the camera's turn (the larger of the angles between the forward
// and between the up axes) plus its displacement seen at the distance to the nearest
// layer (0 inside a layer: there clouds can be as close as the camera is to them, and the
// estimate is the displacement over 1 m), divided by the horizontal angle of a pixel.
// The layers' wind is left out (tens of m/s against the camera's hundreds).
double cloud_motion_px(const FrameContext& prev, const FrameContext& cur);
// From the two frames' contexts (renderer/frame_context.h): their camera frames and each
// layer's wind rotation at its time (the same wind anchor).
Reprojection make_reprojection(const FrameContext& prev, const FrameContext& cur);

// Whether the clouds move by more than quality.fast_motion_px per frame (0 = never).
bool fast_cloud_motion(const Reprojection& r, const RenderQuality& quality);

// Keeps the fast-motion stride (1/4 px) for kFastMotionHoldFrames frames after the last
// fast one: a stride decided afresh every frame could alternate 1/16 and 1/4 with motion
// hovering at the threshold, and the two dither orders interleaved that way leave some
// pixel rows never marched. The hold covers a whole 1/4 cycle. No history: no hold.
constexpr int kFastMotionHoldFrames = 4;
struct FastMotionHold {
  int frames_left = 0;
  bool update(bool fast, bool history) {
    frames_left = !history ? 0 : (fast ? kFastMotionHoldFrames : std::max(0, frames_left - 1));
    return frames_left > 0;
  }
};

// Which cloud pixels a frame marches and what it reuses (CPU side; packed into the
// TemporalUniforms by pack_temporal_uniforms). history: whether the previous buffer is
// usable. The stride is quality.temporal_stride, or at most 2 (1/4 of the pixels) with
// fast_motion (FastMotionHold); without history every pixel is marched.
struct TemporalPlan {
  bool history = false;          // the previous frame's buffer is reprojected
  int stride = 1;                // one cloud pixel in stride x stride is marched
  glm::ivec2 offset{0};          // ... at this offset within its cell (fresh_pixel_offset)
  glm::ivec2 buffer_size{0};     // cloud buffer, cloud pixels
  int divisor = 1;               // frame pixels per cloud pixel, per axis
  bool camera_still = false;     // history && camera_still(prev, cur)
  int footprint_sample = 0;      // footprint_sample_index() of this frame

  double marched_fraction() const { return 1.0 / (static_cast<double>(stride) * stride); }
};
TemporalPlan plan_temporal_frame(const ViewRequest& cur, const RenderQuality& quality, bool history,
                                 const ViewRequest* prev, bool fast_motion = false);

// The uniform block of a plan (reprojection and prev: given when plan.history).
TemporalUniforms pack_temporal_uniforms(const TemporalPlan& plan, const RenderQuality& quality,
                                        const Reprojection* reprojection, const ViewRequest* prev);

// Cloud-buffer size for a frame of w x h frame pixels.
glm::ivec2 cloud_buffer_size(int w, int h, int divisor);

}  // namespace cloudsvc
