// Perlin gradient noise, optionally periodic. See gradient_noise.h.
#include "weather/gradient_noise.h"

#include <cmath>

#include "weather/noise_hash.h"

namespace cloudsvc::weather::detail {
namespace {

// The 12 edge midpoints of a cube (Perlin 2002).
constexpr double kGrad[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                 {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                 {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};

inline double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
inline double lerp(double a, double b, double t) { return a + t * (b - a); }

// Lattice index i and its successor, reduced modulo period when period > 0 (one integer
// division per axis: divisions dominate the cost otherwise).
inline void wrap_pair(long long i, int period, int& i0, int& i1) {
  if (period <= 0) {
    i0 = static_cast<int>(i);
    i1 = i0 + 1;
    return;
  }
  const int m = static_cast<int>(i % period);
  i0 = m < 0 ? m + period : m;
  i1 = i0 + 1 == period ? 0 : i0 + 1;
}

inline double grad_dot(unsigned g, double x, double y, double z) {
  return kGrad[g][0] * x + kGrad[g][1] * y + kGrad[g][2] * z;
}

inline unsigned grad_index(std::uint32_t h) { return h % 12u; }

// Gradient indices of the 8 corners of the cell {x0, x1} x {y0, y1} x {z0, z1} from the
// hash (hash_cell in noise_hash.h, sharing its x and xy stages between corners).
// Order: g[(z << 2) | (y << 1) | x].
struct HashedCorners {
  std::uint32_t seed;
  void operator()(int x0, int x1, int y0, int y1, int z0, int z1, unsigned g[8]) const {
    const std::uint32_t hx0 = hash_x(seed, x0), hx1 = hash_x(seed, x1);
    const std::uint32_t h00 = hash_next(hx0, y0), h10 = hash_next(hx1, y0);
    const std::uint32_t h01 = hash_next(hx0, y1), h11 = hash_next(hx1, y1);
    g[0] = grad_index(hash_next(h00, z0));
    g[1] = grad_index(hash_next(h10, z0));
    g[2] = grad_index(hash_next(h01, z0));
    g[3] = grad_index(hash_next(h11, z0));
    g[4] = grad_index(hash_next(h00, z1));
    g[5] = grad_index(hash_next(h10, z1));
    g[6] = grad_index(hash_next(h01, z1));
    g[7] = grad_index(hash_next(h11, z1));
  }
};

// The same indices read from a period^3 table (periodic noise only).
struct TabledCorners {
  const std::uint8_t* table;
  int period;
  void operator()(int x0, int x1, int y0, int y1, int z0, int z1, unsigned g[8]) const {
    const auto at = [this](int x, int y, int z) {
      return static_cast<unsigned>(table[(static_cast<std::size_t>(z) * period + y) * period + x]);
    };
    g[0] = at(x0, y0, z0);
    g[1] = at(x1, y0, z0);
    g[2] = at(x0, y1, z0);
    g[3] = at(x1, y1, z0);
    g[4] = at(x0, y0, z1);
    g[5] = at(x1, y0, z1);
    g[6] = at(x0, y1, z1);
    g[7] = at(x1, y1, z1);
  }
};

template <typename Corners>
double perlin_impl(double x, double y, double z, int period, const Corners& corners) {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const long long ix = static_cast<long long>(fx);
  const long long iy = static_cast<long long>(fy);
  const long long iz = static_cast<long long>(fz);
  const double dx = x - fx, dy = y - fy, dz = z - fz;
  int x0, x1, y0, y1, z0, z1;
  wrap_pair(ix, period, x0, x1);
  wrap_pair(iy, period, y0, y1);
  wrap_pair(iz, period, z0, z1);
  unsigned g[8];
  corners(x0, x1, y0, y1, z0, z1, g);
  const double n000 = grad_dot(g[0], dx, dy, dz);
  const double n100 = grad_dot(g[1], dx - 1, dy, dz);
  const double n010 = grad_dot(g[2], dx, dy - 1, dz);
  const double n110 = grad_dot(g[3], dx - 1, dy - 1, dz);
  const double n001 = grad_dot(g[4], dx, dy, dz - 1);
  const double n101 = grad_dot(g[5], dx - 1, dy, dz - 1);
  const double n011 = grad_dot(g[6], dx, dy - 1, dz - 1);
  const double n111 = grad_dot(g[7], dx - 1, dy - 1, dz - 1);
  const double u = fade(dx), v = fade(dy), w = fade(dz);
  return lerp(lerp(lerp(n000, n100, u), lerp(n010, n110, u), v),
              lerp(lerp(n001, n101, u), lerp(n011, n111, u), v), w);
}

// Periodic octaves up to this many lattice cells per period read their gradients from a
// table (period^3 bytes, 256 KiB at most) instead of hashing 14 times per sample.
constexpr int kMaxTabledPeriod = 64;

}  // namespace

double perlin_noise(double x, double y, double z, int period, std::uint32_t seed) {
  return perlin_impl(x, y, z, period, HashedCorners{seed});
}

PerlinFbm::PerlinFbm(int octaves, int period, std::uint32_t seed, double gain)
    : octaves_(octaves < 0 ? 0 : (octaves > kMaxOctaves ? kMaxOctaves : octaves)) {
  double weight = 1.0, total = 0.0, scale = 1.0;
  for (int o = 0; o < octaves_; ++o) {
    total += weight;
    weight *= gain;
  }
  weight = 1.0;
  for (int o = 0; o < octaves_; ++o) {
    Octave& oc = oct_[o];
    oc.seed = sub_seed(seed, static_cast<std::uint32_t>(o));
    oc.period = period > 0 ? period << o : 0;
    oc.scale = scale;
    oc.weight = total > 0.0 ? weight / total : 0.0;
    // Offset in [0, 1) lattice cells per axis: a shift does not break periodicity.
    oc.ox = hash_to_unit(hash32(oc.seed ^ 0x1u));
    oc.oy = hash_to_unit(hash32(oc.seed ^ 0x2u));
    oc.oz = hash_to_unit(hash32(oc.seed ^ 0x3u));
    if (oc.period > 0 && oc.period <= kMaxTabledPeriod) {
      const int p = oc.period;
      oc.grad.resize(static_cast<std::size_t>(p) * p * p);
      for (int z = 0; z < p; ++z) {
        for (int y = 0; y < p; ++y) {
          for (int x = 0; x < p; ++x) {
            oc.grad[(static_cast<std::size_t>(z) * p + y) * p + x] =
                static_cast<std::uint8_t>(grad_index(hash_cell(x, y, z, oc.seed)));
          }
        }
      }
    }
    weight *= gain;
    scale *= 2.0;
  }
}

double PerlinFbm::operator()(double x, double y, double z) const {
  double sum = 0.0;
  for (int o = 0; o < octaves_; ++o) {
    const Octave& oc = oct_[o];
    const double px = x * oc.scale + oc.ox, py = y * oc.scale + oc.oy, pz = z * oc.scale + oc.oz;
    const double n = oc.grad.empty()
                         ? perlin_impl(px, py, pz, oc.period, HashedCorners{oc.seed})
                         : perlin_impl(px, py, pz, oc.period, TabledCorners{oc.grad.data(), oc.period});
    sum += oc.weight * n;
  }
  return sum;
}

double perlin_fbm(double x, double y, double z, int octaves, int period, std::uint32_t seed,
                  double gain) {
  return PerlinFbm(octaves, period, seed, gain)(x, y, z);
}

}  // namespace cloudsvc::weather::detail
