// The GPU cloud march of shaders/cloud_march.comp (light: shaders/cloud_lighting.glsl),
// transcribed for a homogeneous flat slab (see slab_renderer_model.h). Comments name the
// shader function or variable each line mirrors.
#include "renderer/model/slab_renderer_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "renderer/model/phase_function.h"

namespace cloudsvc::model {

namespace {

constexpr double kPi = std::numbers::pi;

// cloud_extinction_in (cloud_density.glsl) for the slab: zero outside the open
// height interval (its test f <= 0 || f >= 1), sigma_t inside (coverage 1, profile 1,
// density scale 1, density modulation 1).
double slab_extinction(const SlabSpec& slab, double z) {
  const double f = z / slab.thickness_m;
  if (f <= 0.0 || f >= 1.0) return 0.0;
  return slab.sigma_t_per_m;
}

// 1 - e^{-x} without cancellation (one_minus_exp_neg in common.glsl uses a series below 1e-3 because
// GLSL has no expm1).
double one_minus_exp_neg(double x) { return -std::expm1(-x); }

double cos_sun(const SlabSpec& slab) { return std::cos(slab.sun_zenith_deg * kPi / 180.0); }

}  // namespace

SlabRendererModelOptions converged_renderer_model_options() {
  SlabRendererModelOptions o;
  o.primary_steps = 4096;
  o.min_step_m = 0.0;  // a 1 m floor would cap thin slabs at H / 1 m steps
  return o;
}

// light_optical_depth (cloud_lighting.glsl) in the flat slab, sun above the horizon.
double slab_light_optical_depth(const SlabSpec& slab, double z, const SlabRendererModelOptions& o) {
  const double mu_s = cos_sun(slab);
  if (!(mu_s > 0.0)) return 0.0;
  double len = std::max((slab.thickness_m - z) / mu_s, 0.0);    // exit_top: exit through the top
  // hit_base: the base is never hit on the way up to a sun above the horizon.
  if (o.cap_light_march) len = std::min(len, o.light_max_dist_m);  // min(len, LIGHT_MARCH_REACH_M)
  const int n = o.light_steps;                                      // n
  double tau = 0.0, s_prev = 0.0;
  for (int j = 0; j < n; ++j) {                                     // the loop over j
    const double f = static_cast<double>(j + 1) / n;
    const double s = len * f * f;  // quadratic spacing
    const double zx = z + mu_s * (0.5 * (s + s_prev));              // x, ax: midpoint altitude
    tau += slab_extinction(slab, zx) * (s - s_prev);                // tau += ...
    s_prev = s;
  }
  return tau;
}

namespace {

// diffuse_inscatter (cloud_lighting.glsl) with T_atm = 1, coverage 1, density scale 1,
// E_sun = 1, E_sky = 0 (sky_irradiance) and ground albedo 0: the sun's part alone,
// F_sun times the source table (J_sun). The sun's slab (tilted_sun_slab) is the horizontal
// one here: in a homogeneous slab the light march's depth over its window is w tau_a / mu_s,
// which leaves mu' = mu_s and the column's depths.
// sim: the similarity scale of the slab's phase function (CloudLayerGpu::ms_similarity).
double diffuse_inscatter_scaled(const SlabSpec& slab, double z, const SlabRendererModelOptions& o, const glm::dvec3& w,
                                double sim) {
  const double mu_pos = std::max(cos_sun(slab), 0.0);  // mu_pos
  if (!(mu_pos > 0.0)) return 0.0;
  const double sigma_nominal = slab.sigma_t_per_m * 1.0 * 1.0;                         // sigma_nominal
  const double tau_a = sim * sigma_nominal * std::max(slab.thickness_m - z, 0.0);        // tau_a
  const double tau_b = sim * sigma_nominal * std::max(z - 0.0, 0.0);                     // tau_b
  const double h = std::hypot(w.x, w.y);
  const double cos_phi = h > 1e-12 ? w.x / h : 1.0;                                      // cos_phi (sun towards +x)
  const double phi_deg = std::acos(std::clamp(cos_phi, -1.0, 1.0)) * 180.0 / kPi;       // phi_deg
  const double j_over_mu = o.ms_source_column
                               ? o.ms_source_column->lookup(ms_depth_coordinate(tau_a, tau_b), w.z, phi_deg)
                               : ms_source_table().lookup(tau_a, tau_b, mu_pos, w.z, phi_deg);
  return 1.0 * 1.0 * mu_pos * j_over_mu;                                                 // E_sun T_atm mu_pos J/mu
}

}  // namespace

double slab_diffuse_inscatter(const SlabSpec& slab, double z, const SlabRendererModelOptions& o, const glm::dvec3& w) {
  return diffuse_inscatter_scaled(slab, z, o, w, ms_similarity_scale(jdd_params(slab.droplet_diameter_um)));
}

SlabRendererModelResult slab_renderer_model_radiance(const SlabSpec& slab, const ViewDirection& v, bool top,
                                                     const SlabRendererModelOptions& o) {
  if (!(slab.sigma_t_per_m > 0.0) || !(slab.thickness_m > 0.0) || o.primary_steps < 1 || o.light_steps < 1)
    throw std::invalid_argument("slab renderer model: bad slab or options");
  const JdDParams phase = jdd_params(slab.droplet_diameter_um);
  const double sim = ms_similarity_scale(phase);  // L.ms_similarity
  // Camera ray: opposite to the light's travel direction (dir in cloud_march.comp).
  const glm::dvec3 dir = -view_travel_direction(v, top);
  const glm::dvec3 sun = sun_direction(slab.sun_zenith_deg);
  const double cos_view_sun = glm::dot(dir, sun);  // cos_view_sun
  // The camera sits on the boundary it looks through (top: z = H looking down; bottom:
  // z = 0 looking up); the layer interval is [0, H / |mu|] (ray_intervals, one interval).
  const double z_cam = top ? slab.thickness_m : 0.0;
  const double len = slab.thickness_m / std::fabs(dir.z);
  const double total_len = len;
  const double nominal_dt = std::max(total_len / o.primary_steps, o.min_step_m);  // nominal_du (in t here)
  const int steps = std::max(1, static_cast<int>(std::ceil(len / nominal_dt)));     // steps
  const double dt = len / steps;                                                    // du

  SlabRendererModelResult out;
  const int nj = std::max(1, o.jitter_samples);
  double T_mean = 0.0;
  for (int jj = 0; jj < nj; ++jj) {
    const double jitter = (jj + 0.5) / nj;  // the shader's per-pixel hash12, here stratified
    double C_sun = 0.0, C_diff = 0.0, T = 1.0;
    for (int s = 0; s < steps && T > o.cloud_t_eps; ++s) {  // T > CLOUD_T_EPS
      const double t = (s + jitter) * dt;                   // t
      const double z = z_cam + t * dir.z;                   // p, alt
      const double sigma = slab_extinction(slab, z);        // sigma = cloud_extinction_in(...)
      if (sigma <= 0.0) continue;                           // sigma <= 0: next step
      // L_sun: the peak beam over the light-march optical depth.
      const double tau = slab_light_optical_depth(slab, z, o);  // tau
      const double L_sun = 1.0 * 1.0 *                           // L_sun = E_sun T_atm s_sum
                           (o.peak_beam ? peak_beam_phase(cos_view_sun, tau, phase)
                                        : jdd_phase(cos_view_sun, phase) * std::exp(-tau));
      const double L_diffuse = o.diffuse ? diffuse_inscatter_scaled(slab, z, o, -dir, sim) : 0.0;  // L_diffuse
      const double absorbed = one_minus_exp_neg(sigma * dt);  // absorbed
      C_sun += T * absorbed * L_sun;                          // C += T absorbed (L_sun + L_diffuse)
      C_diff += T * absorbed * L_diffuse;
      T *= 1.0 - absorbed;                                    // T *= 1 - absorbed
    }
    out.radiance_sun += C_sun / nj;
    out.radiance_diffuse += C_diff / nj;
    T_mean += T / nj;
  }
  out.radiance = out.radiance_sun + out.radiance_diffuse;
  out.transmittance = T_mean;
  return out;
}

}  // namespace cloudsvc::model
