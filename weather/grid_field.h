// A scalar field given on the points of a forecast grid (GRIB2: regular or Gaussian
// lat/lon, reduced grids, Lambert conformal, polar stereographic, rotated lat/lon, ...),
// sampled at any geodetic position.
//
// Grids whose points come in rows of one latitude with evenly spaced longitudes (regular
// and reduced lat/lon and Gaussian grids, in any scanning order) are sampled exactly as
// given: linear interpolation along each row (wrapping across the antimeridian when the row
// goes round the globe) and between the two rows around the latitude. Poleward of the
// outermost row of a global grid the value blends linearly to that row's mean, the value at
// the pole, so every longitude meets at the pole without a seam.
//
// Any other grid (projected and rotated ones) is first resampled onto a lat/lon raster over
// the area the points cover, finer than the points' spacing: each point is splatted onto the
// four raster nodes around it with bilinear weights, and nodes no point reached are filled by
// linear interpolation along their row, then their column, across gaps no wider than twice
// the points' spacing (on the ground: a row's reach grows as 1 / cos(latitude)). Nodes
// farther from every point have no data.
//
// Missing values (NaN, from a GRIB bitmap) are left out of the interpolation: the weights of
// the neighbours that have values are renormalised. A position with no value nearby, or
// outside the grid's area, samples as NaN.
#pragma once

#include <span>
#include <vector>

namespace cloudsvc::weather {

class GridField {
 public:
  GridField() = default;

  // From the grid's points in any order as (latitude, longitude in degrees, any range,
  // value), e.g. as ecCodes lists them. Points must be finite in position; values may be
  // NaN (missing). Throws std::invalid_argument for sizes that differ or no points.
  static GridField from_points(std::span<const double> lat_deg, std::span<const double> lon_deg,
                               std::span<const double> values);

  // The value at a geodetic position (degrees; longitude any range), NaN where there is none.
  double at(double lat_deg, double lon_deg) const;

  // True when the grid was sampled as given (rows of one latitude), false when resampled.
  bool exact() const { return exact_; }
  // True when the field covers the whole globe.
  bool global() const { return global_; }
  // The grid's smallest spacing between neighbouring points, degrees of arc (an estimate
  // from its rows or points), e.g. for choosing the resolution of a map made from it.
  double spacing_deg() const { return spacing_deg_; }

 private:
  struct Row {
    double lat_deg = 0.0;
    double lon0_deg = 0.0;  // longitude of the first value, in [0, 360)
    double dlon_deg = 0.0;  // spacing, > 0 (0 for a single point)
    int count = 0;
    std::size_t offset = 0;  // into values_
    bool wraps = false;      // count * dlon_deg covers 360 degrees
    double mean = 0.0;       // mean of the row's values (NaN when all are missing)
  };

  double row_at(const Row& row, double lon_deg) const;
  static GridField from_rows(std::vector<Row> rows, std::vector<float> values);
  static GridField resampled(std::span<const double> lat_deg, std::span<const double> lon_deg,
                             std::span<const double> values);
  static bool try_rows(std::span<const double> lat_deg, std::span<const double> lon_deg,
                       std::span<const double> values, GridField& out);

  std::vector<Row> rows_;      // by ascending latitude
  std::vector<float> values_;  // NaN = missing
  bool exact_ = true;
  bool global_ = false;
  bool pole_south_ = false, pole_north_ = false;  // blend to the pole beyond the outermost row
  double spacing_deg_ = 0.0;
};

}  // namespace cloudsvc::weather
