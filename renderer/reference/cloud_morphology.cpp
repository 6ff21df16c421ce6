#include "renderer/reference/cloud_morphology.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <numbers>

#include "renderer/reference/fourier_transform.h"

namespace cloudsvc::reference {

namespace {

Field channel_field(const FrameImage& img, bool opacity) {
  Field f{img.width, img.height, std::vector<double>(static_cast<std::size_t>(img.width) * img.height)};
  for (std::size_t i = 0; i < f.v.size(); ++i) {
    const float* p = &img.rgba[i * 4];
    f.v[i] = opacity ? p[3] : (static_cast<double>(p[0]) + p[1] + p[2]) / 3.0;
  }
  return f;
}

double median_of(std::vector<double> v) {
  const std::size_t m = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(m), v.end());
  if (v.size() % 2 == 1) return v[m];
  const double hi = v[m];
  return 0.5 * (hi + *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(m)));
}

}  // namespace

Field opacity_field(const FrameImage& img) { return channel_field(img, true); }
Field luminance_field(const FrameImage& img) { return channel_field(img, false); }

double cloud_fraction(const Field& opacity, double threshold) {
  long cloudy = 0;
  for (double a : opacity.v) cloudy += a > threshold ? 1 : 0;
  return static_cast<double>(cloudy) / static_cast<double>(std::max<std::size_t>(opacity.v.size(), 1));
}

std::vector<CloudObject> cloud_objects(const Field& opacity, double threshold) {
  const int w = opacity.width, h = opacity.height;
  std::vector<char> seen(opacity.v.size(), 0);
  auto cloud = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h && opacity.at(x, y) > threshold; };
  std::vector<CloudObject> out;
  std::vector<int> stack;
  for (int y0 = 0; y0 < h; ++y0)
    for (int x0 = 0; x0 < w; ++x0) {
      const int i0 = y0 * w + x0;
      if (seen[i0] || !cloud(x0, y0)) continue;
      CloudObject c;
      seen[i0] = 1;
      stack.push_back(i0);
      while (!stack.empty()) {
        const int i = stack.back();
        stack.pop_back();
        const int x = i % w, y = i / w;
        ++c.area_px;
        if (x == 0 || y == 0 || x == w - 1 || y == h - 1) c.touches_border = true;
        const int nx[4] = {x + 1, x - 1, x, x}, ny[4] = {y, y, y + 1, y - 1};
        for (int k = 0; k < 4; ++k) {
          if (!cloud(nx[k], ny[k])) {
            ++c.perimeter_px;
            continue;
          }
          const int j = ny[k] * w + nx[k];
          if (!seen[j]) {
            seen[j] = 1;
            stack.push_back(j);
          }
        }
      }
      out.push_back(c);
    }
  return out;
}

PowerLawFit fit_power_law(const std::vector<double>& x, const std::vector<double>& y) {
  PowerLawFit fit;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (!(x[i] > 0.0) || !(y[i] > 0.0)) continue;
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly; syy += ly * ly;
    ++fit.n;
  }
  const double n = fit.n;
  const double vx = sxx - sx * sx / std::max(n, 1.0), vy = syy - sy * sy / std::max(n, 1.0);
  const double cxy = sxy - sx * sy / std::max(n, 1.0);
  if (fit.n < 3 || !(vx > 1e-12)) {
    fit.exponent = std::numeric_limits<double>::quiet_NaN();
    return fit;
  }
  fit.exponent = cxy / vx;
  fit.r2 = vy > 0.0 ? cxy * cxy / (vx * vy) : 1.0;
  return fit;
}

PowerLawFit perimeter_area_dimension(const std::vector<CloudObject>& clouds, long min_area_px) {
  std::vector<double> a, p;
  for (const CloudObject& c : clouds)
    if (!c.touches_border && c.area_px >= min_area_px) {
      a.push_back(static_cast<double>(c.area_px));
      p.push_back(static_cast<double>(c.perimeter_px));
    }
  PowerLawFit fit = fit_power_law(a, p);
  fit.exponent *= 2.0;
  return fit;
}

PowerLawFit cloud_size_exponent(const std::vector<CloudObject>& clouds, long min_area_px) {
  std::map<long, int> count_of_area;
  int total = 0;
  for (const CloudObject& c : clouds)
    if (!c.touches_border && c.area_px >= min_area_px) {
      ++count_of_area[c.area_px];
      ++total;
    }
  std::vector<double> a, n_larger;
  int at_least = total;  // clouds with area >= the current one
  for (const auto& [area, count] : count_of_area) {
    a.push_back(static_cast<double>(area));
    n_larger.push_back(static_cast<double>(at_least));
    at_least -= count;
  }
  PowerLawFit fit = fit_power_law(a, n_larger);
  fit.exponent = -fit.exponent;
  return fit;
}

double periodic_autocorrelation_peak(const Field& f, double r_min, double r_max) {
  const int w = f.width, h = f.height;
  double mean = 0.0;
  for (double v : f.v) mean += v;
  mean /= static_cast<double>(std::max<std::size_t>(f.v.size(), 1));
  double var = 0.0;
  for (double v : f.v) var += (v - mean) * (v - mean);
  var /= static_cast<double>(std::max<std::size_t>(f.v.size(), 1));
  if (!(var > 1e-20)) return 0.0;
  // Sums S(dx, dy) = sum of d(x, y) d(x + dx, y + dy) over the overlap, d = f - mean, for
  // every lag at once: the inverse transform of |D|^2 (Wiener-Khinchin) on a grid padded
  // with zeros to at least (w + R) x (h + R), so that no lag up to R wraps onto another.
  const int R = static_cast<int>(std::floor(r_max));
  const std::size_t nx = next_power_of_two(static_cast<std::size_t>(w + std::min(R, w))),
                    ny = next_power_of_two(static_cast<std::size_t>(h + std::min(R, h)));
  std::vector<std::complex<double>> grid(nx * ny, 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) grid[static_cast<std::size_t>(y) * nx + x] = f.at(x, y) - mean;
  fourier_transform_2d(grid, nx, ny, false);
  for (auto& c : grid) c = std::norm(c);
  fourier_transform_2d(grid, nx, ny, true);
  // lags (dx, dy) with dy >= 0 (acf(-l) = acf(l)); dy = 0 only for dx > 0
  std::map<int, std::vector<double>> ring;  // integer radius -> acf values
  std::vector<std::pair<int, double>> lag_acf;
  for (int dy = 0; dy <= std::min(R, h - 1); ++dy)
    for (int dx = -std::min(R, w - 1); dx <= std::min(R, w - 1); ++dx) {
      if (dy == 0 && dx <= 0) continue;
      const double r = std::hypot(static_cast<double>(dx), static_cast<double>(dy));
      if (r < r_min || r > r_max) continue;
      const long n = static_cast<long>(w - std::abs(dx)) * (h - dy);  // pixels of the overlap
      const std::size_t ix = static_cast<std::size_t>(dx < 0 ? static_cast<long>(nx) + dx : dx);
      const double s = grid[static_cast<std::size_t>(dy) * nx + ix].real();
      const double acf = s / static_cast<double>(n) / var;
      const int ri = static_cast<int>(std::lround(r));
      ring[ri].push_back(acf);
      lag_acf.emplace_back(ri, acf);
    }
  std::map<int, double> ring_median;
  for (const auto& [r, v] : ring) ring_median[r] = median_of(v);
  double peak = 0.0;
  for (const auto& [r, acf] : lag_acf) peak = std::max(peak, acf - ring_median[r]);
  return peak;
}

PowerLawFit row_energy_spectrum_slope(const Field& f, double pixel_m, double lambda_min_m, double lambda_max_m) {
  const int w = f.width;
  std::vector<double> power(static_cast<std::size_t>(w / 2 + 1), 0.0), window(static_cast<std::size_t>(w));
  for (int x = 0; x < w; ++x) window[x] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * (x + 0.5) / w);
  std::vector<double> row(static_cast<std::size_t>(w));
  for (int y = 0; y < f.height; ++y) {
    double mean = 0.0;
    for (int x = 0; x < w; ++x) mean += f.at(x, y);
    mean /= w;
    for (int x = 0; x < w; ++x) row[x] = (f.at(x, y) - mean) * window[x];
    for (int k = 1; k <= w / 2; ++k) {  // direct DFT: rows are short (<= a few hundred px)
      std::complex<double> s = 0.0;
      for (int x = 0; x < w; ++x) s += row[x] * std::polar(1.0, -2.0 * std::numbers::pi * k * x / w);
      power[k] += std::norm(s);
    }
  }
  std::vector<double> k_used, e_used;
  for (int k = 1; k <= w / 2; ++k) {
    const double lambda = w * pixel_m / k;
    if (lambda < lambda_min_m || lambda > lambda_max_m) continue;
    k_used.push_back(k);
    e_used.push_back(power[k]);
  }
  return fit_power_law(k_used, e_used);
}

double horizontal_cloud_fraction(const ReferenceScene& scene, const CloudField& field, int li, double alt_m,
                                 double half_width_m, double spacing_m, double sigma_min_per_m) {
  const int n = std::max(1, static_cast<int>(std::floor(2.0 * half_width_m / spacing_m)));
  std::uint64_t evals = 0;
  long cloudy = 0, total = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      // local frame: x east, y north, z up at the camera; the point lifted to alt_m along
      // the shell's up (one correction: the shell is locally flat at these spacings)
      const glm::dvec3 p(-half_width_m + (i + 0.5) * spacing_m, -half_width_m + (j + 0.5) * spacing_m, 0.0);
      glm::dvec3 q = p + (alt_m - scene.shell.altitude_of(p)) * scene.shell.up_at(p);
      q += (alt_m - scene.shell.altitude_of(q)) * scene.shell.up_at(q);
      cloudy += field.sample(li, q, scene.shell.altitude_of(q), true, evals).sigma_t > sigma_min_per_m ? 1 : 0;
      ++total;
    }
  return static_cast<double>(cloudy) / static_cast<double>(total);
}

AnvilRatio anvil_ratio(const ReferenceScene& scene, const CloudField& field, int li, double half_width_m,
                       double spacing_m, double sigma_min_per_m) {
  const ReferenceLayer& L = scene.layers[static_cast<std::size_t>(li)];
  const double depth = L.top_m - L.base_m;
  AnvilRatio a;
  a.mid_fraction =
      horizontal_cloud_fraction(scene, field, li, L.base_m + 0.5 * depth, half_width_m, spacing_m, sigma_min_per_m);
  for (int k = 0; k < 5; ++k) {  // 0.81, 0.85, ..., 0.97 of the depth
    const double alt = L.base_m + (0.81 + 0.04 * k) * depth;
    a.top_fraction =
        std::max(a.top_fraction, horizontal_cloud_fraction(scene, field, li, alt, half_width_m, spacing_m, sigma_min_per_m));
  }
  a.ratio = a.mid_fraction > 0.0 ? a.top_fraction / a.mid_fraction : 0.0;
  return a;
}

}  // namespace cloudsvc::reference
