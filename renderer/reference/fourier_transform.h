// Discrete Fourier transforms of power-of-two length (radix-2 Cooley-Tukey, decimation in
// time), in double: the autocorrelation of renderer/reference/cloud_morphology.h.
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace cloudsvc::reference {

// Smallest power of two >= n (n >= 1).
std::size_t next_power_of_two(std::size_t n);

// In place: a_k = sum_j a_j e^(-+2 pi i jk/N), the minus sign forward; inverse also divides
// by N, so inverse(forward(a)) = a. a.size() must be a power of two.
void fourier_transform(std::vector<std::complex<double>>& a, bool inverse);

// The same over a width x height grid stored row by row (rows, then columns); both sizes
// powers of two.
void fourier_transform_2d(std::vector<std::complex<double>>& a, std::size_t width, std::size_t height, bool inverse);

}  // namespace cloudsvc::reference
