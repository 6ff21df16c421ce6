// PoseTrack interpolation (ECEF chord for position, shortest arc for angles) and
// fixed-rate resampling.
#include "sim_client/pose_track.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim_client/angles.h"

namespace cloudsvc::sim {

namespace {

// Horizontal position between a and b at fraction f in [0, 1]: the point of the ECEF
// chord between the two ground points (height 0) mapped back to latitude/longitude. The
// chord is the short way round, whatever the longitudes' numbering (179.99 vs -179.99).
void interpolate_horizontal(const geo::Geodetic& a, const geo::Geodetic& b, double f,
                            double& lat_deg, double& lon_deg) {
  const glm::dvec3 pa = geo::geodetic_to_ecef({a.lat_deg, a.lon_deg, 0.0});
  const glm::dvec3 pb = geo::geodetic_to_ecef({b.lat_deg, b.lon_deg, 0.0});
  const geo::Geodetic g = geo::ecef_to_geodetic(pa + (pb - pa) * f);
  lat_deg = g.lat_deg;
  // GeographicLib gives +180 for a point on the antimeridian; the readers' range is [-180, 180).
  lon_deg = wrap_lon_deg(g.lon_deg);
}

// An ENU vector given at `at`, expressed in ECEF.
glm::dvec3 enu_to_ecef_vector(const geo::Geodetic& at, const glm::dvec3& v_enu) {
  return geo::enu_to_ecef(at.lat_deg, at.lon_deg) * v_enu;
}

}  // namespace

PoseSample PoseTrack::at(double unix_time_s) const {
  if (samples.empty()) throw std::out_of_range("PoseTrack::at: empty track");
  if (!std::isfinite(unix_time_s)) throw std::invalid_argument("PoseTrack::at: non-finite time");

  if (unix_time_s <= samples.front().unix_time_s || samples.size() == 1) {
    PoseSample s = samples.front();
    s.unix_time_s = unix_time_s;
    return s;
  }
  if (unix_time_s >= samples.back().unix_time_s) {
    PoseSample s = samples.back();
    s.unix_time_s = unix_time_s;
    return s;
  }
  // First sample strictly later than t; its predecessor is at or before t.
  const auto later = std::upper_bound(
      samples.begin(), samples.end(), unix_time_s,
      [](double t, const PoseSample& s) { return t < s.unix_time_s; });
  const PoseSample& a = *(later - 1);
  const PoseSample& b = *later;
  const double f = (unix_time_s - a.unix_time_s) / (b.unix_time_s - a.unix_time_s);

  PoseSample out;
  out.unix_time_s = unix_time_s;
  interpolate_horizontal(a.position, b.position, f, out.position.lat_deg, out.position.lon_deg);
  out.position.alt_m = a.position.alt_m + (b.position.alt_m - a.position.alt_m) * f;

  const geo::Attitude& qa = a.attitude;
  const geo::Attitude& qb = b.attitude;
  out.attitude.heading_deg =
      wrap_deg_360(qa.heading_deg + wrap_deg_180(qb.heading_deg - qa.heading_deg) * f);
  out.attitude.pitch_deg = qa.pitch_deg + (qb.pitch_deg - qa.pitch_deg) * f;
  out.attitude.roll_deg =
      wrap_deg_180(qa.roll_deg + wrap_deg_180(qb.roll_deg - qa.roll_deg) * f);

  if (a.velocity_enu_mps && b.velocity_enu_mps) {
    const glm::dvec3 va = enu_to_ecef_vector(a.position, *a.velocity_enu_mps);
    const glm::dvec3 vb = enu_to_ecef_vector(b.position, *b.velocity_enu_mps);
    // The ENU->ECEF matrix is orthonormal: its transpose maps ECEF back to ENU.
    const glm::dmat3 to_ecef = geo::enu_to_ecef(out.position.lat_deg, out.position.lon_deg);
    out.velocity_enu_mps = glm::transpose(to_ecef) * (va + (vb - va) * f);
  }
  return out;
}

std::vector<PoseSample> resample(const PoseTrack& track, double fps, std::size_t max_frames) {
  if (!std::isfinite(fps) || fps <= 0.0)
    throw std::invalid_argument("resample: fps must be finite and positive");
  if (track.samples.empty()) return {};
  constexpr double kMaxFrames = 50e6;
  const double t0 = track.start_time();
  const double span_frames = (track.end_time() - t0) * fps;  // frames after the first
  // Frames wanted: every one of the span, or the first max_frames (a double, so a span of
  // any length compares without overflowing the integer cast below).
  double wanted = std::floor(span_frames + 1e-9) + 1.0;
  if (max_frames > 0) wanted = std::min(wanted, static_cast<double>(max_frames));
  if (wanted > kMaxFrames)
    throw std::invalid_argument("resample: more than 50 million frames requested");
  const auto count = static_cast<std::size_t>(wanted);
  std::vector<PoseSample> frames;
  frames.reserve(count);
  for (std::size_t k = 0; k < count; ++k)
    frames.push_back(track.at(t0 + static_cast<double>(k) / fps));
  return frames;
}

}  // namespace cloudsvc::sim
