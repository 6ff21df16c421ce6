// Cloud phase function: Jendersie & d'Eon 2023, "An Approximate Mie Scattering
// Function for Fog and Cloud Rendering" (SIGGRAPH talk), HG + Draine blend fitted to Mie
// for water droplets of diameter d (um, 5 <= d <= 50). Parameter fits as printed in
// Ford 2024 eqs. 3.14-3.17 (signs) with the paper's w_D constant 0.665888 (docs/SOURCES.md).
// Double precision: this is
// the reference twin of shaders/phase_function.glsl.
#pragma once

namespace cloudsvc::model {

struct JdDParams {
  double g_hg = 0.0;   // HG lobe asymmetry
  double g_d = 0.0;    // Draine lobe asymmetry
  double alpha = 0.0;  // Draine alpha
  double w_d = 0.0;    // weight of the Draine lobe
};

// Fitted parameters for a droplet diameter in micrometres (clamped to [5, 50]).
JdDParams jdd_params(double diameter_um);

// Phase functions in sr^-1, each normalised to 1 over the sphere. cos_theta is the cosine
// of the scattering angle (1 = forward).
double hg_phase(double cos_theta, double g);
double draine_phase(double cos_theta, double g, double alpha);
double jdd_phase(double cos_theta, const JdDParams& p);

// Mean cosine <cos theta> of the blend (closed form: Draine 2003 for the Draine lobe,
// g for the HG lobe). Used to map the phase to a single asymmetry parameter.
double jdd_mean_cosine(const JdDParams& p);

}  // namespace cloudsvc::model
