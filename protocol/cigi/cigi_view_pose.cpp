// A CIGI view's eye point and attitude (cigi_view_pose.h).
#include "protocol/cigi/cigi_view_pose.h"

namespace cloudsvc::cigi {
ViewPose view_pose(const OwnshipPose& ownship, const View& view) {
  const geo::Geodetic own{ownship.lat_deg, ownship.lon_deg, ownship.alt_m};
  const geo::BodyAxes body = geo::body_axes_enu({ownship.yaw_deg, ownship.pitch_deg, ownship.roll_deg});
  // The view's axes in the body frame, taken as a level frame (east = right, north =
  // forward, up = up), then in the ownship's local ENU.
  const geo::BodyAxes in_body = geo::body_axes_enu({view.yaw_deg, view.pitch_deg, view.roll_deg});
  const auto to_enu = [&](const glm::dvec3& b) { return b.x * body.right + b.y * body.forward + b.z * body.up; };
  const glm::dvec3 f = to_enu(in_body.forward), r = to_enu(in_body.right), u = to_enu(in_body.up);
  // The eye: offsets along the body axes (z down).
  const glm::dvec3 offset = static_cast<double>(view.x_m) * body.forward + static_cast<double>(view.y_m) * body.right -
                            static_cast<double>(view.z_m) * body.up;
  const glm::dmat3 own_to_ecef = geo::enu_to_ecef(own.lat_deg, own.lon_deg);
  ViewPose out;
  out.position = geo::ecef_to_geodetic(geo::geodetic_to_ecef(own) + own_to_ecef * offset);
  // The axes in the eye's own local frame (a few metres away: nearly the same).
  const glm::dmat3 ecef_to_eye = glm::transpose(geo::enu_to_ecef(out.position.lat_deg, out.position.lon_deg));
  const geo::BodyAxes eye{ecef_to_eye * (own_to_ecef * f), ecef_to_eye * (own_to_ecef * r), ecef_to_eye * (own_to_ecef * u)};
  out.attitude = geo::attitude_of(eye);
  return out;
}

}  // namespace cloudsvc::cigi
