// Sampling of forecast-grid fields (grid_field.h).
#include "weather/grid_field.h"

#include "weather/sphere_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cloudsvc::weather {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Latitudes closer than this are one row (degrees; ecCodes computes them in double).
constexpr double kSameLatitude_deg = 1e-7;
// Largest raster the resampling of an irregular grid builds (nodes): 16 Mi floats.
constexpr std::size_t kMaxRasterNodes = std::size_t{1} << 24;

double wrap360(double lon_deg) {
  double r = std::fmod(lon_deg, 360.0);
  if (r < 0.0) r += 360.0;
  return r >= 360.0 ? 0.0 : r;
}

// Linear interpolation that leaves out a missing end: a value where one end has one.
double mix_present(double a, double b, double t) {
  if (std::isnan(a)) return b;
  if (std::isnan(b)) return a;
  return a + (b - a) * t;
}

double mean_present(std::span<const float> v) {
  double sum = 0.0;
  int n = 0;
  for (float x : v)
    if (!std::isnan(x)) sum += x, ++n;
  return n > 0 ? sum / n : kNaN;
}

}  // namespace

GridField GridField::from_points(std::span<const double> lat_deg, std::span<const double> lon_deg,
                                 std::span<const double> values) {
  if (lat_deg.size() != lon_deg.size() || lat_deg.size() != values.size())
    throw std::invalid_argument("grid field: latitudes, longitudes and values differ in number");
  if (lat_deg.empty()) throw std::invalid_argument("grid field: no points");
  for (std::size_t i = 0; i < lat_deg.size(); ++i)
    if (!std::isfinite(lat_deg[i]) || !std::isfinite(lon_deg[i]) || std::abs(lat_deg[i]) > 90.0 + 1e-9)
      throw std::invalid_argument("grid field: point " + std::to_string(i) + " has no valid position");
  GridField rows;
  if (try_rows(lat_deg, lon_deg, values, rows)) return rows;
  return resampled(lat_deg, lon_deg, values);
}

bool GridField::try_rows(std::span<const double> lat_deg, std::span<const double> lon_deg,
                         std::span<const double> values, GridField& out) {
  std::vector<Row> rows;
  std::vector<float> row_values;
  row_values.reserve(values.size());
  std::size_t begin = 0;
  while (begin < lat_deg.size()) {
    std::size_t end = begin + 1;
    while (end < lat_deg.size() && std::abs(lat_deg[end] - lat_deg[begin]) <= kSameLatitude_deg) ++end;
    Row row;
    row.lat_deg = std::clamp(lat_deg[begin], -90.0, 90.0);
    row.count = static_cast<int>(end - begin);
    row.offset = row_values.size();
    // Evenly spaced longitudes, in either direction.
    double step = 0.0;
    if (row.count > 1) {
      step = std::remainder(lon_deg[begin + 1] - lon_deg[begin], 360.0);
      if (std::abs(step) < 1e-9) return false;
      for (std::size_t k = begin + 1; k < end; ++k)
        if (std::abs(std::remainder(lon_deg[k] - lon_deg[k - 1] - step, 360.0)) > 1e-6 * std::max(1.0, std::abs(step)))
          return false;
    }
    const bool reversed = step < 0.0;
    row.dlon_deg = std::abs(step);
    row.lon0_deg = wrap360(reversed ? lon_deg[end - 1] : lon_deg[begin]);
    row.wraps = row.count > 1 && row.count * row.dlon_deg >= 360.0 - 0.5 * row.dlon_deg;
    if (row.count * row.dlon_deg > 360.0 + 0.5 * row.dlon_deg) return false;  // overlapping longitudes
    for (std::size_t k = 0; k < end - begin; ++k)
      row_values.push_back(static_cast<float>(values[reversed ? end - 1 - k : begin + k]));
    rows.push_back(row);
    begin = end;
  }
  // Rows must follow each other in latitude, in one direction.
  if (rows.size() < 2) return false;
  const bool south_to_north = rows[1].lat_deg > rows[0].lat_deg;
  for (std::size_t r = 1; r < rows.size(); ++r)
    if ((rows[r].lat_deg > rows[r - 1].lat_deg) != south_to_north || rows[r].lat_deg == rows[r - 1].lat_deg) return false;
  // A row of one point stands for a pole only.
  for (const Row& row : rows)
    if (row.count == 1 && std::abs(row.lat_deg) < 90.0 - 1e-6) return false;
  if (!south_to_north) std::reverse(rows.begin(), rows.end());
  out = from_rows(std::move(rows), std::move(row_values));
  return true;
}

GridField GridField::from_rows(std::vector<Row> rows, std::vector<float> values) {
  GridField f;
  f.rows_ = std::move(rows);
  f.values_ = std::move(values);
  double spacing = 180.0;
  bool all_wrap = true;
  for (std::size_t r = 0; r < f.rows_.size(); ++r) {
    Row& row = f.rows_[r];
    row.mean = mean_present(std::span<const float>(f.values_).subspan(row.offset, static_cast<std::size_t>(row.count)));
    all_wrap = all_wrap && (row.wraps || row.count == 1);
    if (r > 0) spacing = std::min(spacing, row.lat_deg - f.rows_[r - 1].lat_deg);
  }
  // Along rows: the spacing on the ground of the row nearest the equator (rows converge
  // towards the poles, where their spacing says nothing of the grid's resolution).
  const Row* equator = nullptr;
  for (const Row& row : f.rows_)
    if (row.count > 1 && (!equator || std::abs(row.lat_deg) < std::abs(equator->lat_deg))) equator = &row;
  if (equator) spacing = std::min(spacing, equator->dlon_deg * std::cos(equator->lat_deg * kRadPerDeg));
  f.spacing_deg_ = spacing;
  const Row& south = f.rows_.front();
  const Row& north = f.rows_.back();
  const double south_gap = f.rows_[1].lat_deg - south.lat_deg;
  const double north_gap = north.lat_deg - f.rows_[f.rows_.size() - 2].lat_deg;
  f.pole_south_ = all_wrap && south.lat_deg > -90.0 && south.lat_deg + 90.0 <= 1.5 * south_gap;
  f.pole_north_ = all_wrap && north.lat_deg < 90.0 && 90.0 - north.lat_deg <= 1.5 * north_gap;
  f.global_ = all_wrap && (south.lat_deg <= -90.0 || f.pole_south_) && (north.lat_deg >= 90.0 || f.pole_north_);
  return f;
}

double GridField::row_at(const Row& row, double lon_deg) const {
  const float* v = values_.data() + row.offset;
  if (row.count == 1) return v[0];
  double u = wrap360(lon_deg - row.lon0_deg) / row.dlon_deg;
  if (row.wraps) {
    const double fl = std::floor(u);
    const int i0 = static_cast<int>(fl) % row.count;
    const int i1 = (i0 + 1) % row.count;
    return mix_present(v[i0], v[i1], u - fl);
  }
  const double last = row.count - 1;
  if (u > last + 1e-9) {
    // Just west of the first point by rounding: at the first point.
    if ((360.0 / row.dlon_deg - u) <= 1e-9) u = 0.0;
    else return kNaN;
  }
  u = std::min(u, last);
  const int i0 = std::min(static_cast<int>(std::floor(u)), row.count - 2);
  return mix_present(v[i0], v[i0 + 1], u - i0);
}

double GridField::at(double lat_deg, double lon_deg) const {
  if (rows_.empty() || !std::isfinite(lat_deg) || !std::isfinite(lon_deg)) return kNaN;
  const double lat = std::clamp(lat_deg, -90.0, 90.0);
  const Row& south = rows_.front();
  const Row& north = rows_.back();
  if (lat < south.lat_deg) {
    if (!pole_south_) return kNaN;
    const double t = (south.lat_deg - lat) / (south.lat_deg + 90.0);
    return mix_present(row_at(south, lon_deg), south.mean, t);
  }
  if (lat > north.lat_deg) {
    if (!pole_north_) return kNaN;
    const double t = (lat - north.lat_deg) / (90.0 - north.lat_deg);
    return mix_present(row_at(north, lon_deg), north.mean, t);
  }
  auto upper = std::upper_bound(rows_.begin(), rows_.end(), lat, [](double l, const Row& r) { return l < r.lat_deg; });
  if (upper == rows_.end()) return row_at(north, lon_deg);
  const Row& b = *upper;
  const Row& a = *(upper - 1);
  const double t = (lat - a.lat_deg) / (b.lat_deg - a.lat_deg);
  return mix_present(row_at(a, lon_deg), row_at(b, lon_deg), t);
}

GridField GridField::resampled(std::span<const double> lat_deg, std::span<const double> lon_deg,
                               std::span<const double> values) {
  const std::size_t n = lat_deg.size();
  // Spacing: the median distance between points that follow each other (neighbours in
  // every scanning order but at the ends of scan lines).
  std::vector<double> steps;
  steps.reserve(n);
  for (std::size_t i = 1; i < n; ++i) {
    const double d = arc_between(unit_vector(lat_deg[i - 1], lon_deg[i - 1]), unit_vector(lat_deg[i], lon_deg[i])) / kRadPerDeg;
    if (d > 0.0) steps.push_back(d);
  }
  double s = 1.0;
  if (!steps.empty()) {
    std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
    s = steps[steps.size() / 2];
  }
  s = std::max(s, 1e-4);

  // The area: latitude range, and longitude range as the circle minus its largest gap.
  double lat_min = 90.0, lat_max = -90.0;
  std::vector<double> lons(n);
  for (std::size_t i = 0; i < n; ++i) {
    lat_min = std::min(lat_min, lat_deg[i]);
    lat_max = std::max(lat_max, lat_deg[i]);
    lons[i] = wrap360(lon_deg[i]);
  }
  std::sort(lons.begin(), lons.end());
  double gap = lons.front() + 360.0 - lons.back(), lon_min = lons.front(), lon_span = lons.back() - lons.front();
  for (std::size_t i = 1; i < n; ++i)
    if (lons[i] - lons[i - 1] > gap) {
      gap = lons[i] - lons[i - 1];
      lon_min = lons[i];
      lon_span = 360.0 - gap;
    }
  const bool full_circle = gap < std::max(10.0, 4.0 * s);
  if (full_circle) {
    lon_min = 0.0;
    lon_span = 360.0;
    if (lat_max > 90.0 - 2.0 * s) lat_max = 90.0;  // the points surround a pole
    if (lat_min < -90.0 + 2.0 * s) lat_min = -90.0;
  }

  double step = s / 2.0;
  const auto nodes = [&](double span) { return static_cast<std::size_t>(std::ceil(span / step)) + 1; };
  while (nodes(lon_span) * nodes(lat_max - lat_min) > kMaxRasterNodes) step *= 1.25;
  const int width = full_circle ? std::max(2, static_cast<int>(std::lround(360.0 / step))) : static_cast<int>(nodes(lon_span));
  const int height = static_cast<int>(nodes(lat_max - lat_min));
  const double dlon = full_circle ? 360.0 / width : step;
  const double dlat = height > 1 ? (lat_max - lat_min) / (height - 1) : step;

  // Splat: bilinear weights onto the four nodes around each point.
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<float> weight(count, 0.0f), value_weight(count, 0.0f), value_sum(count, 0.0f);
  for (std::size_t p = 0; p < n; ++p) {
    double x = wrap360(lon_deg[p] - lon_min) / dlon;
    if (!full_circle && x > width - 1) x = (x * dlon > 180.0 + lon_span / 2) ? 0.0 : width - 1;
    const double y = std::clamp((lat_deg[p] - lat_min) / dlat, 0.0, static_cast<double>(height - 1));
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const double fx = x - x0, fy = y - y0;
    const bool present = !std::isnan(values[p]);
    for (int dy = 0; dy <= 1; ++dy)
      for (int dx = 0; dx <= 1; ++dx) {
        int xi = x0 + dx, yi = y0 + dy;
        if (yi >= height) continue;
        if (xi >= width) {
          if (!full_circle) continue;
          xi -= width;
        }
        const float w = static_cast<float>((dx ? fx : 1.0 - fx) * (dy ? fy : 1.0 - fy));
        if (w <= 0.0f) continue;
        const std::size_t k = static_cast<std::size_t>(yi) * width + xi;
        weight[k] += w;
        if (present) {
          value_weight[k] += w;
          value_sum[k] += w * static_cast<float>(values[p]);
        }
      }
  }
  constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> raster(count, kNaNf);
  std::vector<char> known(count, 0);
  for (std::size_t k = 0; k < count; ++k) {
    if (weight[k] <= 0.0f) continue;
    known[k] = 1;
    if (value_weight[k] > 0.0f) raster[k] = value_sum[k] / value_weight[k];
  }

  // Fill gaps between known nodes along a line of `len` nodes (stride apart), no wider
  // than `reach` nodes; `ring` lines wrap round.
  const auto fill_line = [&](std::size_t first, std::size_t stride, int len, double reach, bool ring) {
    int prev = -1, first_known = -1;
    for (int i = 0; i < len; ++i) {
      if (!known[first + i * stride]) continue;
      if (first_known < 0) first_known = i;
      if (prev >= 0 && i - prev > 1 && i - prev <= reach) {
        const float a = raster[first + prev * stride], b = raster[first + i * stride];
        for (int g = prev + 1; g < i; ++g) {
          raster[first + g * stride] = static_cast<float>(mix_present(a, b, double(g - prev) / (i - prev)));
          known[first + g * stride] = 2;
        }
      }
      prev = i;
    }
    if (ring && first_known >= 0 && prev >= 0) {
      const int span = first_known + len - prev;
      if (span > 1 && span <= reach) {
        const float a = raster[first + prev * stride], b = raster[first + first_known * stride];
        for (int g = 1; g < span; ++g) {
          const int i = (prev + g) % len;
          raster[first + i * stride] = static_cast<float>(mix_present(a, b, double(g) / span));
          known[first + i * stride] = 2;
        }
      }
    }
  };
  for (int j = 0; j < height; ++j) {
    const double lat = lat_min + j * dlat;
    const double reach = 2.0 * s / (dlon * std::max(std::cos(lat * kRadPerDeg), 1e-3));
    fill_line(static_cast<std::size_t>(j) * width, 1, width, reach, full_circle);
  }
  for (int i = 0; i < width; ++i) fill_line(static_cast<std::size_t>(i), width, height, 2.0 * s / dlat, false);
  for (std::size_t k = 0; k < count; ++k)
    if (!known[k]) raster[k] = kNaNf;

  std::vector<Row> rows(height);
  for (int j = 0; j < height; ++j) {
    Row& r = rows[j];
    r.lat_deg = std::clamp(lat_min + j * dlat, -90.0, 90.0);
    r.lon0_deg = wrap360(lon_min);
    r.dlon_deg = dlon;
    r.count = width;
    r.offset = static_cast<std::size_t>(j) * width;
    r.wraps = full_circle;
  }
  if (height < 2) {  // a single row of points: widen to two identical rows
    rows.push_back(rows.front());
    rows.back().lat_deg = std::min(90.0, rows.front().lat_deg + 1e-9);
  }
  GridField f = from_rows(std::move(rows), std::move(raster));
  f.exact_ = false;
  f.spacing_deg_ = s;
  return f;
}

}  // namespace cloudsvc::weather
