// What to draw: the camera pose, time and image size of one frame. Plain data shared by
// the GPU renderer and the CPU reference (no GL).
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>

#include "geodesy/geodetic.h"

namespace cloudsvc {

// The edges of an off-axis view (CIGI View Definition): angles from the view axis, degrees,
// left < right and bottom < top, each within (-90, 90).
struct ViewFrustumAngles {
  double left_deg = -30.0, right_deg = 30.0, bottom_deg = -17.5, top_deg = 17.5;
  bool operator==(const ViewFrustumAngles&) const = default;
};

// The image on the plane at unit distance along the view axis: the tangents of its centre
// (0 for a symmetric view) and of its half width and height, x right, y up. A pixel's ray
// is forward + (center_x + ndc_x half_x) right + (center_y + ndc_y half_y) up.
struct ImageWindow {
  double center_x = 0.0, center_y = 0.0, half_x = 1.0, half_y = 1.0;
  // The half extents of the smallest symmetric window holding this one.
  double bound_x() const { return std::abs(center_x) + half_x; }
  double bound_y() const { return std::abs(center_y) + half_y; }
  bool operator==(const ImageWindow&) const = default;
};

// One view: where the camera is, where it looks, when, and the image size.
struct ViewRequest {
  geo::Geodetic position;      // WGS84, altitude above the ellipsoid (m)
  geo::Attitude attitude;      // heading/pitch/roll, degrees
  double unix_time_s = 0.0;    // UTC, seconds since 1970-01-01
  double fov_deg = 60.0;       // horizontal field of view
  int width = 640;
  int height = 360;
  std::uint32_t frame_index = 0;  // varies the per-pixel jitter and the temporally marched pixels
  bool reset_history = false;     // a teleport or sim reset: reuse nothing from earlier frames
  std::optional<ViewFrustumAngles> frustum;  // an off-axis view's edges; else fov_deg, symmetric,
                                             // its height from the image's aspect
  int channel = 0;  // the display channel the view is drawn for: each channel keeps its own
                    // temporal history and frame; the weather, shadow map and LUTs are shared
  // Near and far planes (CIGI View Definition), m along the view axis: clouds closer than
  // near_m or beyond far_m are not drawn (they still shade and shadow the rest); the sky,
  // the ground and the air are drawn whole. 0 = no plane.
  double near_m = 0.0, far_m = 0.0;
};

// The distances along a unit ray between which clouds are drawn, for planes near_m and
// far_m (ViewRequest; 0 = none) and the ray's cosine with the view axis (> 0 inside any
// frustum): [near_m / cos_axis, far_m / cos_axis]; no far plane: 1e300.
struct CloudClip {
  double t0 = 0.0, t1 = 1e300;
};
inline CloudClip cloud_clip(double near_m, double far_m, double cos_axis) {
  CloudClip c;
  if (!(cos_axis > 0.0)) return c;
  if (near_m > 0.0) c.t0 = near_m / cos_axis;
  if (far_m > 0.0) c.t1 = far_m / cos_axis;
  return c;
}

// The view's image window: from its frustum's edges, else symmetric from fov_deg with the
// vertical extent of the image's aspect (square pixels).
inline ImageWindow image_window(const ViewRequest& v) {
  constexpr double kRad = 3.14159265358979323846 / 180.0;
  if (v.frustum) {
    const double l = std::tan(v.frustum->left_deg * kRad), r = std::tan(v.frustum->right_deg * kRad);
    const double b = std::tan(v.frustum->bottom_deg * kRad), t = std::tan(v.frustum->top_deg * kRad);
    return {0.5 * (l + r), 0.5 * (b + t), 0.5 * (r - l), 0.5 * (t - b)};
  }
  const double half_x = std::tan(0.5 * v.fov_deg * kRad);
  return {0.0, 0.0, half_x, half_x * static_cast<double>(v.height) / static_cast<double>(v.width)};
}

}  // namespace cloudsvc
