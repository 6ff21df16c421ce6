// Band-by-band ray walk of the ground truth (see band_walker.h).
#include "renderer/truth/band_walker.h"

#include <algorithm>
#include <cmath>

#include "renderer/reference/shell_crossings.h"

namespace cloudsvc::truth {

BandWalker::BandWalker(const TruthWorld& world, const glm::dvec3& x0, const glm::dvec3& w, double air_scale,
                       double air_floor)
    : world_(world), x0_(x0), w_(w), air_scale_(air_scale), air_floor_(air_floor) {
  const double r = glm::length(x0);
  h0_ = r - world.radius_m;
  mu_ = std::clamp(glm::dot(x0, w) / r, -1.0, 1.0);
  const int bands = static_cast<int>(world.band_majorant.size());
  if (h0_ >= world.top_alt_m) {
    // Above the medium: enter through the top sphere if the ray reaches it.
    const auto top = reference::sphere_crossings(world.radius_m, h0_, world.top_alt_m, mu_);
    if (!top || top->t0 <= 0.0) {
      band_ = bands;
      end_ = End::Top;
      return;
    }
    t_ = top->t0;
    band_ = bands - 1;
    return;
  }
  // The band the ray goes into: a start on an edge belongs to the band below when the ray
  // heads down (find_segment takes only crossings strictly ahead, so it would never see
  // the edge it starts on and the ray would cross the planet in the band above).
  const auto& e = world.band_edges;
  const auto it = mu_ < 0.0 ? std::lower_bound(e.begin(), e.end(), h0_) : std::upper_bound(e.begin(), e.end(), h0_);
  band_ = static_cast<int>(it - e.begin()) - 1;
  if (band_ < 0 && mu_ < 0.0) {  // on or below the ground, heading down: there already
    end_ = End::Ground;
    return;
  }
  band_ = std::clamp(band_, 0, bands - 1);
}

void BandWalker::find_segment() {
  const double outer = world_.band_edges[static_cast<std::size_t>(band_ + 1)];
  const double inner = world_.band_edges[static_cast<std::size_t>(band_)];
  // Leaving through the outer sphere (far root); if rounding puts the ray outside it, now.
  const auto o = reference::sphere_crossings(world_.radius_m, h0_, outer, mu_);
  seg_end_ = o ? std::max(o->t1, t_) : t_;
  next_band_ = band_ + 1;
  const auto i = reference::sphere_crossings(world_.radius_m, h0_, inner, mu_);
  if (i && i->t0 > t_ && i->t0 < seg_end_) {
    seg_end_ = i->t0;
    next_band_ = band_ - 1;
  }
  const std::size_t b = static_cast<std::size_t>(band_);
  const double air = std::max(air_floor_, air_scale_ * world_.band_air_majorant[b]);
  double cloud = world_.band_majorant[b] - world_.band_air_majorant[b];
  if (world_.local && world_.band_local[b] && cloud > 0.0) {
    if (seg_end_ - t_ > world_.local_stretch_m) {
      seg_end_ = t_ + world_.local_stretch_m;
      next_band_ = band_;
    }
    cloud = std::min(cloud, world_.local->cloud_bound(band_, x0_ + t_ * w_, x0_ + seg_end_ * w_));
  }
  seg_majorant_ = air + cloud;
  segment_known_ = true;
}

double BandWalker::advance(double tau, double& majorant) {
  const int bands = static_cast<int>(world_.band_majorant.size());
  while (end_ == End::None) {
    if (!segment_known_) find_segment();
    const double m = seg_majorant_;
    const double room = seg_end_ - t_;
    if (m > 0.0 && tau < room * m) {
      t_ += tau / m;
      majorant = m;
      return t_;
    }
    tau -= room * m;
    t_ = seg_end_;
    band_ = next_band_;
    segment_known_ = false;
    if (band_ < 0) end_ = End::Ground;
    if (band_ >= bands) end_ = End::Top;
  }
  return kInfinity;
}

}  // namespace cloudsvc::truth
