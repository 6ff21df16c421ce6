// Small integer hashes for deterministic procedural noise (internal to weather/).
// std::rand is not used: its sequence is implementation-defined, and noise must be the
// same on every platform for a given seed. hash32 is the "lowbias32" integer finaliser
// (C. Wellons, "Prospecting for hash functions", 2018, public domain constants).
#pragma once

#include <cstdint>

namespace cloudsvc::weather::detail {

constexpr std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

// Hash of an integer lattice point and a seed, built one axis at a time so that callers
// visiting the corners of a lattice cell can share the x and xy stages:
//   hash_cell = hash_z(hash_y(hash_x(seed, x), y), z).
// Coordinates are taken as two's-complement 32-bit values, so negative cells hash fine.
constexpr std::uint32_t hash_x(std::uint32_t seed, std::int32_t x) {
  return hash32((seed * 0x9e3779b1U + 0x7f4a7c15U) ^ static_cast<std::uint32_t>(x));
}
constexpr std::uint32_t hash_next(std::uint32_t h, std::int32_t c) {
  return hash32(h ^ static_cast<std::uint32_t>(c));
}
constexpr std::uint32_t hash_cell(std::int32_t x, std::int32_t y, std::int32_t z,
                                  std::uint32_t seed) {
  return hash_next(hash_next(hash_x(seed, x), y), z);
}

// A derived seed for sub-stream k of a seed (channels, octaves).
constexpr std::uint32_t sub_seed(std::uint32_t seed, std::uint32_t k) {
  return hash32(seed * 0x9e3779b1U + hash32(k + 0x68bc21ebU));
}

// Uniform float in [0, 1) from the top 24 bits of a hash.
constexpr float hash_to_unit(std::uint32_t h) {
  return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

}  // namespace cloudsvc::weather::detail
