#include "weather/dome_rings.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <shared_mutex>
#include <stdexcept>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace cloudsvc::weather {

namespace {
double ring_step_m(const RingLayout& layout, int ring) { return layout.size / 8 * ring_texel_m(layout, ring); }
}  // namespace

DomeRings dome_rings_for(const RingLayout& layout, const glm::dvec3& camera_field) {
  if (layout.rings > kDomeMaxRings || layout.size % 8 != 0)
    throw std::invalid_argument("dome rings: at most 4 rings of a multiple of 8 texels");
  const double R = kDomeShellRadius_m;
  const glm::dvec3 nadir = R * glm::normalize(camera_field);
  DomeRings r;
  const glm::dvec3 cell = glm::floor(nadir / kDomeAnchorCell_m) + 0.5;
  r.anchor = R * glm::normalize(cell);
  r.plane = ring_plane(r.anchor);
  const glm::dvec2 uv = ring_plane_coords(r.plane, R, nadir);
  for (int k = 0; k < layout.rings; ++k) {
    const double step = ring_step_m(layout, k);
    r.origin[k] = glm::round(uv / step) * step;
  }
  return r;
}

double dome_ring_weight(const RingLayout& layout, const DomeRings& rings, int ring, const glm::dvec2& uv) {
  const glm::dvec2 t = glm::abs(uv - rings.origin[ring]) / ring_texel_m(layout, ring);
  const double inner = 0.5 * layout.size - 1.5;  // the bilinear footprint stays inside
  const double reach = std::max(t.x, t.y), fade = 0.125 * 0.5 * layout.size;
  return std::clamp((inner - reach) / fade, 0.0, 1.0);
}

struct DomeTopSampler::Cache {
  struct Key {
    std::int64_t ax, ay, az;  // anchor (m, rounded)
    int ring;
    long long i, j;
    bool operator==(const Key&) const = default;
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::size_t h = std::hash<long long>()(k.i * 73856093LL ^ k.j * 19349663LL ^ k.ring * 83492791LL);
      return h ^ std::hash<std::int64_t>()(k.ax * 31 + k.ay * 17 + k.az);
    }
  };
  mutable std::shared_mutex mutex;
  std::unordered_map<Key, DomeRingTexel, Hash> texels;
};

DomeTopSampler::DomeTopSampler(const CloudPlacement& cp, const DomeWarp& warp, const DomeSubgrid& subgrid,
                               const RingLayout& layout, CloudPlacement::CoverageAt coverage)
    : cp_(cp), warp_(warp), subgrid_(subgrid), layout_(layout), coverage_(std::move(coverage)), cache_(new Cache) {}

DomeTopSampler::~DomeTopSampler() { delete cache_; }

DomeRingTexel DomeTopSampler::texel(const DomeRings& rings, int ring, long long mi, long long mj) const {
  const Cache::Key key{std::llround(rings.anchor.x), std::llround(rings.anchor.y), std::llround(rings.anchor.z), ring, mi,
                       mj};
  {
    const std::shared_lock lock(cache_->mutex);
    const auto it = cache_->texels.find(key);
    if (it != cache_->texels.end()) return it->second;
  }
  const double h = ring_texel_m(layout_, ring);
  const DomeRingTexel t =
      dome_ring_texel_at(cp_, warp_, layout_, rings.plane, rings.anchor, ring, {(mi + 0.5) * h, (mj + 0.5) * h}, coverage_);
  const std::unique_lock lock(cache_->mutex);
  cache_->texels.emplace(key, t);
  return t;
}

DomeRingTexel DomeTopSampler::ring_bilinear(const DomeRings& rings, int ring, const glm::dvec2& uv) const {
  const double h = ring_texel_m(layout_, ring);
  const glm::dvec2 g = uv / h - 0.5;  // in global texel units, texel m's centre at m
  const glm::dvec2 f = glm::floor(g), w = g - f;
  const long long i = static_cast<long long>(f.x), j = static_cast<long long>(f.y);
  const DomeRingTexel a = texel(rings, ring, i, j), b = texel(rings, ring, i + 1, j), c = texel(rings, ring, i, j + 1),
                      d = texel(rings, ring, i + 1, j + 1);
  const auto mix2 = [&](double va, double vb, double vc, double vd) {
    return (1.0 - w.y) * ((1.0 - w.x) * va + w.x * vb) + w.y * ((1.0 - w.x) * vc + w.x * vd);
  };
  return {mix2(a.top_m, b.top_m, c.top_m, d.top_m),
          mix2(a.covered_below, b.covered_below, c.covered_below, d.covered_below)};
}

double DomeTopSampler::top_m(const DomeRings& rings, const glm::dvec3& x, double coverage_here) const {
  const glm::dvec2 uv = ring_plane_coords(rings.plane, cp_.shell_radius_m(), x);
  const double floor_m = dome_ring_floor_m(layout_, layout_.rings - 1);
  const int levels = cp_.params().levels;
  // from the finest ring holding x outwards: rep_k weighted w_k, the rest to the coarser
  // representations (all sub-grid beyond the last ring)
  double result = 0.0, remaining = 1.0;
  for (int k = 0; k < layout_.rings && remaining > 0.0; ++k) {
    const double w = dome_ring_weight(layout_, rings, k, uv);
    if (w <= 0.0) continue;
    const DomeRingTexel t = ring_bilinear(rings, k, uv);
    const double rep =
        std::max(t.top_m, subgrid_.top_m(x, ring_first_level(layout_, cp_.params(), k), t.covered_below, floor_m));
    result += remaining * w * rep;
    remaining -= remaining * w;
  }
  // over every level the covered fraction is the coverage itself (as far as the placement
  // reaches; CloudPlacement::covered_below agrees within 2e-3)
  if (remaining > 0.0)
    result += remaining * subgrid_.top_m(x, levels, std::min(coverage_here, cp_.max_coverage()), floor_m);
  return result;
}

}  // namespace cloudsvc::weather
