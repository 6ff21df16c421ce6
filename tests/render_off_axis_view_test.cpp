// Off-axis views (ViewRequest::frustum, the CIGI View Definition's half-angles): a view whose
// edges are 0° and 30° right of its axis shows what the right half of a symmetric 60° view
// shows, pixel for pixel; likewise the upper half; a centred view of the same size does not.
#include <gtest/gtest.h>

#include <cmath>

#include "render_test_support.h"
#include "weather/presets.h"

namespace cloudsvc::test {
namespace {

constexpr double kDeg = M_PI / 180.0;

ViewRequest base_view() {
  ViewRequest v;
  v.position = {47.0, 8.0, 2500.0};
  v.attitude = {90.0, 4.0, 0.0};
  v.unix_time_s = 1782043200.0;  // 2026-06-21T12:00:00Z
  v.fov_deg = 60.0;
  v.width = 128;
  v.height = 64;
  return v;
}

// Mean over the pixels of |a - b| in luminance, relative to the mean luminance of b, with a
// at columns [ax, ax + b.width) and rows [ay, ay + b.height).
double relative_difference(const FrameImage& a, int ax, int ay, const FrameImage& b) {
  double diff = 0.0, sum = 0.0;
  for (int y = 0; y < b.height; ++y)
    for (int x = 0; x < b.width; ++x) {
      diff += std::abs(luminance(a.pixel(ax + x, ay + y)) - luminance(b.pixel(x, y)));
      sum += luminance(b.pixel(x, y));
    }
  return diff / sum;
}

TEST(OffAxisView, AnOffAxisViewIsTheMatchingPartOfAWiderSymmetricOne) {
  CloudRenderer& r = shared_renderer();
  r.set_weather(*weather::preset("broken-cumulus"));
  const RenderQuality q{};
  const ViewRequest wide_view = base_view();
  const FrameImage wide = render_still_view(r, wide_view, q);
  maybe_save("off_axis_wide", wide);
  const double half_y_deg = std::atan(std::tan(30.0 * kDeg) * 64.0 / 128.0) / kDeg;

  // The right half: 64 x 64 pixels from the axis to 30° right.
  ViewRequest right = wide_view;
  right.width = 64;
  right.frustum = ViewFrustumAngles{0.0, 30.0, -half_y_deg, half_y_deg};
  const FrameImage right_img = render_still_view(r, right, q);
  maybe_save("off_axis_right", right_img);
  EXPECT_EQ(count_bad_values(right_img), 0);
  const double right_error = relative_difference(wide, 64, 0, right_img);

  // The upper half: 128 x 32 pixels from the axis up.
  ViewRequest upper = wide_view;
  upper.height = 32;
  upper.frustum = ViewFrustumAngles{-30.0, 30.0, 0.0, half_y_deg};
  const FrameImage upper_img = render_still_view(r, upper, q);
  const double upper_error = relative_difference(wide, 0, 0, upper_img);

  // A centred view of the right half's size (64 x 64, the same 30° width) is another picture.
  ViewRequest centred = right;
  centred.frustum = ViewFrustumAngles{-15.0, 15.0, -half_y_deg, half_y_deg};
  const FrameImage centred_img = render_still_view(r, centred, q);
  const double wrong = relative_difference(wide, 64, 0, centred_img);

  std::printf("off-axis: right half %.4f, upper half %.4f, centred (wrong) %.4f\n", right_error, upper_error, wrong);
  EXPECT_LT(right_error, 0.04);
  EXPECT_LT(upper_error, 0.04);
  EXPECT_GT(wrong, 4.0 * std::max(right_error, upper_error)) << "the comparison tells views apart";
}

}  // namespace
}  // namespace cloudsvc::test
