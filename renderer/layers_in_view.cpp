#include "renderer/layers_in_view.h"

#include <algorithm>
#include <cmath>

namespace cloudsvc {
namespace {

const glm::dvec3 kZenith{0.0, 0.0, 1.0};

// Does direction d of the camera's view fall inside the frustum (its image coordinates
// within [-1, 1]^2 and in front)?
bool in_frustum(const glm::dvec3& d, const glm::dvec3& f, const glm::dvec3& r, const glm::dvec3& u, double tx,
                double ty) {
  const double depth = glm::dot(d, f);
  if (depth <= 0.0) return false;
  return std::abs(glm::dot(d, r)) <= tx * depth && std::abs(glm::dot(d, u)) <= ty * depth;
}

// Extend range by the extremes of z on the great-circle arc from unit a to unit b (< 180 deg).
void arc_extremes(const glm::dvec3& a, const glm::dvec3& b, MuRange& range) {
  range.min = std::min({range.min, a.z, b.z});
  range.max = std::max({range.max, a.z, b.z});
  const glm::dvec3 n_raw = glm::cross(a, b);
  const double nl = glm::length(n_raw);
  if (nl < 1e-15) return;
  const glm::dvec3 n = n_raw / nl;
  const glm::dvec3 p_raw = kZenith - n.z * n;  // the circle's highest point, unnormalised
  const double pl = glm::length(p_raw);
  if (pl < 1e-15) return;  // the circle is horizontal: z is constant on it
  const glm::dvec3 p = p_raw / pl;
  // p (or -p) is on the arc when it lies between a and b in the circle's sense
  auto on_arc = [&](const glm::dvec3& q) { return glm::dot(glm::cross(a, q), n) >= 0.0 && glm::dot(glm::cross(q, b), n) >= 0.0; };
  if (on_arc(p)) range.max = std::max(range.max, p.z);
  if (on_arc(-p)) range.min = std::min(range.min, -p.z);
}

// 1 - ((R + a) / (R + h))^2 without cancellation: (h - a)(2R + h + a) / (R + h)^2.
double one_minus_ratio_sq(double R, double h, double a) { return (h - a) * (2.0 * R + h + a) / ((R + h) * (R + h)); }

}  // namespace

MuRange frustum_mu_range(const glm::dvec3& f, const glm::dvec3& r, const glm::dvec3& u, double tx, double ty) {
  glm::dvec3 c[4];
  const double sx[4] = {-1.0, 1.0, 1.0, -1.0}, sy[4] = {-1.0, -1.0, 1.0, 1.0};  // around the rectangle
  for (int i = 0; i < 4; ++i) c[i] = glm::normalize(f + sx[i] * tx * r + sy[i] * ty * u);
  MuRange range{1.0, -1.0};
  for (int i = 0; i < 4; ++i) arc_extremes(c[i], c[(i + 1) % 4], range);
  if (in_frustum(kZenith, f, r, u, tx, ty)) range.max = 1.0;
  if (in_frustum(-kZenith, f, r, u, tx, ty)) range.min = -1.0;
  return range;
}

FrameRays classify_frame_rays(const FrameContext& c) {
  // (an off-axis view's symmetric bound: its zenith range can only be wider)
  const MuRange mu = frustum_mu_range(c.axes.forward, c.axes.right, c.axes.up, c.window.bound_x(), c.window.bound_y());
  // the GPU's axes are these rounded to float: the range is widened by a margin far above
  // their rounding (1e-6), far below a pixel (1e-4 rad)
  const double margin = 1e-5;
  const double R = c.shell_radius_m, h = c.camera_altitude_m, ground = c.ground_altitude_m;
  // zenith cosine of the rays tangent to the ground sphere from the camera (rays below hit it)
  const double mu_ground = h > ground ? -std::sqrt(std::max(0.0, one_minus_ratio_sq(R, h, ground))) : 0.0;
  FrameRays out;
  out.sees_ground = mu.min < mu_ground + margin;
  // a drawn layer whose base is at or above layer i's top (shaders/layers_above.glsl)
  const auto has_layer_above = [&c](int i) {
    for (int j = 0; j < c.layer_count; ++j)
      if (j != i && c.layers[static_cast<size_t>(j)].drawn_coverage() > 0.0 &&
          c.layers[static_cast<size_t>(j)].layer.base_m >= c.layers[static_cast<size_t>(i)].layer.top_m)
        return true;
    return false;
  };
  for (int i = 0; i < c.layer_count; ++i) {
    const LayerFrame& L = c.layers[static_cast<size_t>(i)];
    if (L.drawn_coverage() <= 0.0) continue;  // culled or clear: not marched
    const double base = L.layer.base_m, top = L.layer.top_m;
    bool in_view;
    if (h >= top)  // rays below the top sphere's tangent meet it
      in_view = mu.min < -std::sqrt(std::max(0.0, one_minus_ratio_sq(R, h, top))) + margin;
    else if (h >= base)  // inside the layer
      in_view = true;
    else  // below the base: every ray that does not hit the ground first reaches the base sphere
      in_view = mu.max > mu_ground - margin;
    out.meets_a_layer = out.meets_a_layer || in_view;
    out.meets_a_layer_under_another = out.meets_a_layer_under_another || (in_view && has_layer_above(i));
  }
  return out;
}

}  // namespace cloudsvc
