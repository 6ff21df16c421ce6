// Tentative collisions along a straight ray through the majorant bands of a TruthWorld:
// the ray x0 + t w (t >= 0) is followed band by band (each band the shell between two
// concentric spheres, its majorant constant), and advance(tau) moves by an optical depth
// tau of the majorant, i.e. to the next event of the Poisson process of rate
// majorant(t) (Novak et al. 2018, CGF 37(2), §4.1: exponential free-flight sampling in a
// piecewise-constant majorant).
//
// Crossings are computed from the ray's start with the cancellation-free sphere roots of
// shell_crossings.h, one band at a time: inside band b the ray leaves through the outer
// sphere at its far root, or enters the inner sphere at its near root if that lies ahead.
// A band is re-entered only through a root strictly beyond the current distance, so a
// point on a boundary never re-detects the sphere it has just crossed; a ray that starts
// on a boundary starts in the band it heads into (below it when it heads down). Bands the world
// refines locally (TruthWorld::local) are cut into stretches of local_stretch_m, each with
// its own majorant.
#pragma once

#include <limits>

#include <glm/glm.hpp>

#include "renderer/truth/truth_world.h"

namespace cloudsvc::truth {

class BandWalker {
 public:
  enum class End { None, Ground, Top };

  // air_scale multiplies the air's part of each band's majorant (>= 1; more tentative
  // collisions on camera rays, where they carry next-event estimates); air_floor (1/m,
  // >= 0) is the least value of that part in every band (next events in the thin, sunlit
  // upper air at twilight).
  BandWalker(const TruthWorld& world, const glm::dvec3& x0, const glm::dvec3& w, double air_scale = 1.0,
             double air_floor = 0.0);

  // Moves to the next tentative collision at majorant optical depth tau (> 0) ahead;
  // returns its distance and sets majorant, or returns infinity once the ray has hit the
  // ground or left through the top (end() says which, distance() where).
  double advance(double tau, double& majorant);

  End end() const { return end_; }
  double distance() const { return t_; }

 private:
  void find_segment();  // sets seg_end_, next_band_ and seg_majorant_ for band_

  const TruthWorld& world_;
  glm::dvec3 x0_, w_;           // the ray
  double h0_ = 0.0, mu_ = 0.0;  // start altitude and zenith cosine of the ray
  double seg_majorant_ = 0.0;
  double air_scale_ = 1.0, air_floor_ = 0.0;
  int band_ = 0;                 // current band; -1 = ground, size = above the top
  double t_ = 0.0;               // current distance
  double seg_end_ = 0.0;         // where the ray leaves band_
  int next_band_ = 0;
  bool segment_known_ = false;
  End end_ = End::None;
};

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace cloudsvc::truth
