#include "renderer/reference/fourier_transform.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace cloudsvc::reference {

std::size_t next_power_of_two(std::size_t n) {
  std::size_t p = 1;
  while (p < n) p <<= 1;
  return p;
}

void fourier_transform(std::vector<std::complex<double>>& a, bool inverse) {
  const std::size_t n = a.size();
  if (n == 0 || (n & (n - 1)) != 0) throw std::invalid_argument("fourier_transform: length is not a power of two");
  // bit-reversal permutation
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i], a[j]);
  }
  // butterflies over blocks of len, twiddles e^(-+2 pi i k/len) from one root each
  const double sign = inverse ? 1.0 : -1.0;
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const std::size_t half = len / 2;
    for (std::size_t k = 0; k < half; ++k) {
      const std::complex<double> w = std::polar(1.0, sign * 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(len));
      for (std::size_t i = k; i < n; i += len) {
        const std::complex<double> u = a[i], v = a[i + half] * w;
        a[i] = u + v;
        a[i + half] = u - v;
      }
    }
  }
  if (inverse)
    for (auto& x : a) x /= static_cast<double>(n);
}

void fourier_transform_2d(std::vector<std::complex<double>>& a, std::size_t width, std::size_t height, bool inverse) {
  if (a.size() != width * height) throw std::invalid_argument("fourier_transform_2d: size is not width x height");
  std::vector<std::complex<double>> line(width);
  for (std::size_t y = 0; y < height; ++y) {
    std::copy_n(a.begin() + static_cast<std::ptrdiff_t>(y * width), width, line.begin());
    fourier_transform(line, inverse);
    std::copy(line.begin(), line.end(), a.begin() + static_cast<std::ptrdiff_t>(y * width));
  }
  line.resize(height);
  for (std::size_t x = 0; x < width; ++x) {
    for (std::size_t y = 0; y < height; ++y) line[y] = a[y * width + x];
    fourier_transform(line, inverse);
    for (std::size_t y = 0; y < height; ++y) a[y * width + x] = line[y];
  }
}

}  // namespace cloudsvc::reference
