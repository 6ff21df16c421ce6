// Cloud morphology measured on images, for comparison with observations (issue 15):
//  - the clouds of a mask (opacity above a threshold; 4-connected pixels), their areas and
//    4-neighbour perimeters (pixel edges between cloud and clear, the image border
//    included), and whether they touch the border;
//  - the perimeter-area dimension D: P ∝ A^(D/2) fitted by least squares in log-log over
//    all clouds of at least a given area that do not touch the border (Lovejoy 1982:
//    D ≈ 1.35 for satellite and radar clouds over 1 to 10^6 km^2; 1 for smooth outlines,
//    2 for outlines that fill space);
//  - the cloud-size distribution: the number of clouds larger than A, N(>A) ∝ A^(-b)
//    (Cahalan & Joseph 1989 find power laws for cumulus fields);
//  - the strongest periodic peak of a field's autocorrelation over the median of its ring
//    (radii from r_min to r_max pixels): a field with no repetition scores ~0.05, a tiled
//    one up to 1;
//  - the slope β of the energy spectrum along the rows, E(k) ∝ k^β over a band of
//    wavelengths (Cahalan & Snider 1989: β ≈ -5/3 for marine stratocumulus radiance over
//    0.5 to ~10 km);
//  - from the density field itself (the CPU reference's CloudField): the fraction of a
//    horizontal area that is cloud at each altitude of a layer, and the anvil ratio of a
//    cumulonimbus layer = the largest fraction in the layer's top fifth over the fraction
//    at mid-height (>= 2 for anvils spreading under the tropopause; <= 1 for pillars).
#pragma once

#include <vector>

#include "renderer/api/frame_image.h"
#include "renderer/reference/cloud_field.h"
#include "renderer/reference/reference_scene.h"

namespace cloudsvc::reference {

// A scalar image, row-major, row 0 at the top.
struct Field {
  int width = 0, height = 0;
  std::vector<double> v;
  double at(int x, int y) const { return v[static_cast<std::size_t>(y) * width + x]; }
};

Field opacity_field(const FrameImage& img);    // the a channel
Field luminance_field(const FrameImage& img);  // mean of r, g, b (linear radiance)

// Fraction of the field's pixels whose value is above threshold (the cloud mask's area).
double cloud_fraction(const Field& opacity, double threshold = 0.5);

struct CloudObject {
  long area_px = 0;       // pixels
  long perimeter_px = 0;  // pixel edges between the cloud and clear pixels or the border
  bool touches_border = false;
};

// The 4-connected clouds of the pixels whose value is above threshold.
std::vector<CloudObject> cloud_objects(const Field& opacity, double threshold = 0.5);

// y ∝ x^exponent fitted in log-log by least squares over n points; r2 its coefficient of
// determination. exponent is NaN with fewer than 3 points or no spread in x.
struct PowerLawFit {
  double exponent = 0.0;
  double r2 = 0.0;
  int n = 0;
};
PowerLawFit fit_power_law(const std::vector<double>& x, const std::vector<double>& y);

// D of P ∝ A^(D/2) (2 x the fitted exponent) over the clouds of at least min_area_px that
// do not touch the border.
PowerLawFit perimeter_area_dimension(const std::vector<CloudObject>& clouds, long min_area_px = 10);

// b of N(>A) ∝ A^(-b) (minus the fitted exponent, so b > 0) over the same clouds, the
// complementary cumulative count evaluated at each distinct area.
PowerLawFit cloud_size_exponent(const std::vector<CloudObject>& clouds, long min_area_px = 10);

// max over lags with r_min <= |lag| <= r_max (pixels) of acf(lag) - median of acf over the
// lags of the same integer radius; acf = the autocovariance over the overlap of the field
// and its shifted copy, divided by the field's variance (1 at lag 0). 0 for a constant
// field.
double periodic_autocorrelation_peak(const Field& f, double r_min, double r_max);

// β of E(k) ∝ k^β: the power spectrum of each row (mean removed, Hann window), averaged
// over the rows, fitted over the wavenumbers whose wavelength (width * pixel_m / k) lies in
// [lambda_min_m, lambda_max_m].
PowerLawFit row_energy_spectrum_slope(const Field& f, double pixel_m, double lambda_min_m, double lambda_max_m);

// Fraction of the points of a square horizontal grid (side 2 half_width_m, spacing_m,
// centred under the scene's camera) at altitude alt_m above the shell sphere where layer
// li's extinction (detail noise included) exceeds sigma_min_per_m.
double horizontal_cloud_fraction(const ReferenceScene& scene, const CloudField& field, int li, double alt_m,
                                 double half_width_m, double spacing_m, double sigma_min_per_m);

struct AnvilRatio {
  double top_fraction = 0.0;  // largest cloud fraction at the altitudes of the top fifth
  double mid_fraction = 0.0;  // cloud fraction at mid-height
  double ratio = 0.0;         // top / mid (0 when mid is 0)
};
// Over layer li, sampling 5 altitudes across its top fifth and one at mid-height.
AnvilRatio anvil_ratio(const ReferenceScene& scene, const CloudField& field, int li, double half_width_m,
                       double spacing_m, double sigma_min_per_m);

}  // namespace cloudsvc::reference
