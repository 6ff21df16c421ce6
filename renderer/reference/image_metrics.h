// Error metrics between two frames on linear radiance, rgb channels only:
//   RMSE      = sqrt(mean over pixels and channels of (test - ref)^2)   (W m^-2 sr^-1 nm^-1)
//   relative  = RMSE / mean over pixels and channels of ref
//   PSNR      = 10 log10(peak^2 / MSE) dB, peak = the reference's largest rgb value
//               (so a frame with the sun disk in view would score high: compare views
//               without it, or pass a fixed peak)
//   max error = largest |test - ref| of any channel, and where it is
// plus the RMSE of the opacity channel (a); and the cloud silhouettes of two frames (which
// pixels are cloud, and the error on the reference's cloud edges).
#pragma once

#include "renderer/api/frame_image.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"

namespace cloudsvc::reference {

struct ImageDifference {
  double rmse = 0.0;
  double relative_rmse = 0.0;
  double psnr_db = 0.0;
  double peak = 0.0;           // peak used for the PSNR
  double mean_reference = 0.0;
  double max_error = 0.0;
  int max_error_x = 0, max_error_y = 0;
  double opacity_rmse = 0.0;
};

// Images must have the same size. fixed_peak > 0 replaces the reference's peak.
ImageDifference compare_images(const FrameImage& test, const FrameImage& reference, double fixed_peak = 0.0);

// Fraction of img's pixels that are cloud (opacity above kCloudPixelOpacity).
double cloud_pixel_fraction(const FrameImage& img);

// Which pixels are cloud (opacity above kCloudPixelOpacity) in a test frame against a
// reference, as fractions of all pixels, and the error on the reference's cloud edges.
struct SilhouetteDifference {
  double test_cloud = 0.0, reference_cloud = 0.0;  // cloud-pixel fractions
  double false_cloud = 0.0;   // cloud in the test, clear in the reference (a dilated silhouette)
  double missed_cloud = 0.0;  // clear in the test, cloud in the reference
  // rgb RMSE (as compare_images) over the edge band: pixels whose neighbourhood of
  // (2 edge_radius_px + 1)^2 pixels in the reference holds both cloud and clear pixels
  double edge_rmse = 0.0;
  int edge_pixels = 0;
};
// Images must have the same size.
SilhouetteDifference compare_silhouettes(const FrameImage& test, const FrameImage& reference, int edge_radius_px = 2);

// The mean of each n x n block of img (rgba; width and height divisible by n): the box-
// filtered footprint of one pixel of the 1/n image (n = 1: img itself).
FrameImage box_downsample(const FrameImage& img, int n);

}  // namespace cloudsvc::reference
