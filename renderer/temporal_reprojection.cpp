#include "renderer/temporal_reprojection.h"

#include <cmath>

namespace cloudsvc {

namespace {


// Ordered-dither visiting orders: each prefix of 4 (of 16) covers the 2x2 sub-grid evenly.
constexpr int kOrder2[4][2] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
constexpr int kOrder4[16][2] = {{0, 0}, {2, 2}, {2, 0}, {0, 2}, {1, 1}, {3, 3}, {3, 1}, {1, 3},
                                {1, 0}, {3, 2}, {3, 0}, {1, 2}, {0, 1}, {2, 3}, {2, 1}, {0, 3}};

bool same_march(const RenderQuality& a, const RenderQuality& b) {
  return a.primary_steps == b.primary_steps && a.light_steps == b.light_steps && a.column_steps == b.column_steps &&
         a.column_volume == b.column_volume && a.sun_slab_tilt == b.sun_slab_tilt &&
         a.ground_shadow_steps == b.ground_shadow_steps &&
         a.step_growth_ref_m == b.step_growth_ref_m && a.temporal_stride == b.temporal_stride &&
         a.cloud_resolution_divisor == b.cloud_resolution_divisor && a.long_step_factor == b.long_step_factor &&
         a.level_of_detail == b.level_of_detail && a.temporal_reuse == b.temporal_reuse &&
         a.ground_shadow_map == b.ground_shadow_map && a.light_volume == b.light_volume &&
         a.coverage_pyramid == b.coverage_pyramid && a.light_march_cutoff == b.light_march_cutoff;
}

// current local -> previous local for a field that moves by the ECEF rotation q (the
// position X' at the previous time of the material now at X is q X).
glm::dmat4 local_transform(const glm::dmat3& q, const FrameContext& prev, const FrameContext& cur) {
  const glm::dvec3& cam_cur = cur.camera_ecef;
  const glm::dvec3& cam_prev = prev.camera_ecef;
  const glm::dmat3& e_cur = cur.enu_to_ecef;
  const glm::dmat3& e_prev = prev.enu_to_ecef;
  const glm::dmat3 a = glm::transpose(e_prev) * q * e_cur;
  // q cam_cur - cam_prev without cancellation: (cam_cur - cam_prev) + (q - I) cam_cur
  const glm::dvec3 b = glm::transpose(e_prev) * ((cam_cur - cam_prev) + (q - glm::dmat3(1.0)) * cam_cur);
  glm::dmat4 m(a);
  m[3] = glm::dvec4(b, 1.0);
  return m;
}

}  // namespace

bool camera_still(const ViewRequest& prev, const ViewRequest& cur) {
  const double moved = glm::length(geo::geodetic_to_ecef(cur.position) - geo::geodetic_to_ecef(prev.position));
  const auto turned = [](double a, double b) { return std::abs(std::remainder(a - b, 360.0)); };
  return moved < kStillCameraM && turned(prev.attitude.heading_deg, cur.attitude.heading_deg) < kStillCameraDeg &&
         turned(prev.attitude.pitch_deg, cur.attitude.pitch_deg) < kStillCameraDeg &&
         turned(prev.attitude.roll_deg, cur.attitude.roll_deg) < kStillCameraDeg;
}

int footprint_sample_index(int still_frames, int stride) {
  const int per_cycle = std::max(1, stride) * std::max(1, stride);
  return still_frames <= 0 ? 0 : (still_frames + per_cycle - 1) / per_cycle;
}

int footprint_sample_index(bool temporal_reuse, std::uint32_t frame_index, int still_frames, int stride) {
  return temporal_reuse ? footprint_sample_index(still_frames, stride) : static_cast<int>(frame_index % 65536u);
}

glm::ivec2 fresh_pixel_offset(int stride, std::uint32_t frame_index) {
  if (stride == 2) return {kOrder2[frame_index % 4][0], kOrder2[frame_index % 4][1]};
  if (stride == 4) return {kOrder4[frame_index % 16][0], kOrder4[frame_index % 16][1]};
  return {0, 0};
}

glm::ivec2 cloud_buffer_size(int w, int h, int divisor) {
  return {(w + divisor - 1) / divisor, (h + divisor - 1) / divisor};
}

bool history_usable(const ViewRequest& prev, const RenderQuality& prev_quality, const ViewRequest& cur,
                    const RenderQuality& cur_quality) {
  if (cur.reset_history || !cur_quality.temporal_reuse || !prev_quality.temporal_reuse) return false;
  if (prev.width != cur.width || prev.height != cur.height || image_window(prev) != image_window(cur)) return false;
  if (prev.near_m != cur.near_m || prev.far_m != cur.far_m) return false;  // other clouds clipped
  if (!same_march(prev_quality, cur_quality)) return false;
  const double gap = cur.unix_time_s - prev.unix_time_s;
  if (!(gap >= 0.0 && gap <= kMaxHistoryGapS)) return false;
  const double jump = glm::length(geo::geodetic_to_ecef(cur.position) - geo::geodetic_to_ecef(prev.position));
  if (jump > kMaxHistoryJumpM) return false;
  const geo::BodyAxes a = geo::body_axes_enu(prev.attitude), b = geo::body_axes_enu(cur.attitude);
  return glm::dot(a.forward, b.forward) >= std::cos(kMaxHistoryTurnDeg * M_PI / 180.0);
}

Reprojection make_reprojection(const FrameContext& prev, const FrameContext& cur) {
  Reprojection r;
  const glm::dmat4 ground = local_transform(glm::dmat3(1.0), prev, cur);
  for (auto& t : r.transform) t = ground;
  const int n = std::min(cur.layer_count, prev.layer_count);
  for (int i = 0; i < n; ++i) {
    // The field is sampled at rot(t) X: material at X now sat at rot(prev)^T rot(cur) X.
    const glm::dmat3 q = glm::transpose(prev.layers[static_cast<size_t>(i)].field_rotation) *
                         cur.layers[static_cast<size_t>(i)].field_rotation;
    r.transform[i] = local_transform(q, prev, cur);
  }
  r.prev_axes = prev.axes;
  r.cloud_motion_px = cloud_motion_px(prev, cur);
  return r;
}

double cloud_motion_px(const FrameContext& prev, const FrameContext& cur) {
  if (cur.layer_count == 0) return 0.0;
  const geo::BodyAxes& a = prev.axes;
  const geo::BodyAxes& b = cur.axes;
  // both sets of axes in ECEF (the local frames of the two positions differ)
  const glm::dmat3& ea = prev.enu_to_ecef;
  const glm::dmat3& eb = cur.enu_to_ecef;
  const auto angle = [](glm::dvec3 u, glm::dvec3 v) { return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v)); };
  const double turn = std::max(angle(ea * a.forward, eb * b.forward), angle(ea * a.up, eb * b.up));
  double nearest_m = 1e30;
  for (int i = 0; i < cur.layer_count; ++i) {
    const weather::CloudLayer& l = cur.layers[static_cast<size_t>(i)].layer;
    const double alt = cur.camera_altitude_m;
    const double d = alt < l.base_m ? l.base_m - alt : (alt > l.top_m ? alt - l.top_m : 0.0);
    nearest_m = std::min(nearest_m, d);
  }
  const double moved_m = glm::length(cur.camera_ecef - prev.camera_ecef);
  const double parallax = std::atan(moved_m / std::max(nearest_m, 1.0));
  const double pixel_rad = 2.0 * std::atan(cur.window.half_x) / static_cast<double>(std::max(cur.view.width, 1));
  return (turn + parallax) / pixel_rad;
}

bool fast_cloud_motion(const Reprojection& r, const RenderQuality& quality) {
  return quality.fast_motion_px > 0.0 && r.cloud_motion_px > quality.fast_motion_px;
}

TemporalPlan plan_temporal_frame(const ViewRequest& cur, const RenderQuality& quality, bool history,
                                 const ViewRequest* prev, bool fast_motion) {
  TemporalPlan p;
  p.divisor = std::max(1, quality.cloud_resolution_divisor);
  p.buffer_size = cloud_buffer_size(cur.width, cur.height, p.divisor);
  p.history = history;
  p.stride = history ? std::max(1, quality.temporal_stride) : 1;
  if (history && fast_motion) p.stride = std::min(p.stride, 2);
  p.offset = fresh_pixel_offset(p.stride, cur.frame_index);
  p.camera_still = history && prev && camera_still(*prev, cur);
  return p;
}

TemporalUniforms pack_temporal_uniforms(const TemporalPlan& p, const RenderQuality& quality,
                                        const Reprojection* reprojection, const ViewRequest* prev) {
  TemporalUniforms u{};
  u.fresh_stride = p.stride;
  u.fresh_offset = p.offset;
  u.history_valid = p.history ? 1 : 0;
  u.cloud_buffer_size = p.buffer_size;
  u.cloud_divisor = p.divisor;
  u.neighbourhood_clamp = quality.neighbourhood_clamp ? 1 : 0;
  u.history_blend_min = static_cast<float>(quality.history_blend_min);
  u.camera_still = p.camera_still ? 1 : 0;
  u.footprint_sample = p.footprint_sample;
  for (auto& m : u.reproject) m = glm::mat4(1.0f);
  if (p.history && reprojection && prev) {
    for (int i = 0; i <= gpu::kMaxLayers; ++i) u.reproject[i] = glm::mat4(reprojection->transform[i]);
    u.prev_forward = glm::vec3(reprojection->prev_axes.forward);
    u.prev_right = glm::vec3(reprojection->prev_axes.right);
    u.prev_up = glm::vec3(reprojection->prev_axes.up);
    const ImageWindow w = image_window(*prev);
    u.prev_tan_half_fov_x = static_cast<float>(w.half_x);
    u.prev_tan_half_fov_y = static_cast<float>(w.half_y);
    u.prev_center_tan_x = static_cast<float>(w.center_x);
    u.prev_center_tan_y = static_cast<float>(w.center_y);
  }
  return u;
}

}  // namespace cloudsvc
