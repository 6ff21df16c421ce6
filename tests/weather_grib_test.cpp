// GRIB2 cloud fields through ecCodes (weather/grib_reader.h, grid_field.h,
// gridded_weather.h) on files made here from ecCodes' own samples: every grid type the
// reader supports, both cover unit conventions, bitmaps, forecast steps, and bad files.
#include <eccodes.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

#include "grib_test_support.h"
#include "weather/gridded_weather.h"
#include "weather/standard_atmosphere.h"
#include "weather/weather_json.h"

namespace {

using namespace cloudsvc::weather;
using cloudsvc::test::append_cloud_field;
using cloudsvc::test::append_grib_message;
using cloudsvc::test::GribKey;
using cloudsvc::test::GribTempDir;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// The test field: smooth, periodic in longitude, the same at every longitude at the poles.
double cover_fraction(double lat, double lon) { return 0.5 + 0.3 * std::sin(2.0 * lat * kDeg) * std::cos(lon * kDeg); }
double cover_percent(double lat, double lon) { return 100.0 * cover_fraction(lat, lon); }

// Keys of total cloud cover in % (WMO 0/6/1, ecCodes paramId 228164) or as a fraction
// (ECMWF local paramId 164), valid 2026-06-01 12 UTC.
std::vector<GribKey> tcc(bool percent, std::vector<GribKey> grid = {}) {
  std::vector<GribKey> keys = std::move(grid);
  keys.push_back({"paramId", percent ? 228164L : 164L});
  keys.push_back({"dataDate", 20260601L});
  keys.push_back({"dataTime", 1200L});
  keys.push_back({"stepRange", std::string("0")});
  return keys;
}

GribCloudMessage only_message(const std::filesystem::path& file) {
  GribReadResult r = read_grib_cloud_fields(file.string());
  EXPECT_EQ(r.clouds.size(), 1u);
  return r.clouds.empty() ? GribCloudMessage{} : std::move(r.clouds.front());
}

// Grid points as ecCodes places them (for projected grids: test positions between them).
struct GridPoints {
  std::vector<double> lat, lon;
  long ni = 0;
};
GridPoints grid_points(const std::filesystem::path& file) {
  GridPoints g;
  FILE* f = std::fopen(file.c_str(), "rb");
  int err = 0;
  codes_handle* h = codes_handle_new_from_file(nullptr, f, PRODUCT_GRIB, &err);
  std::size_t n = 0;
  codes_get_size(h, "latitudes", &n);
  g.lat.resize(n);
  g.lon.resize(n);
  codes_get_double_array(h, "latitudes", g.lat.data(), &n);
  codes_get_double_array(h, "longitudes", g.lon.data(), &n);
  if (codes_get_long(h, "Nx", &g.ni) != 0) codes_get_long(h, "Ni", &g.ni);
  codes_handle_delete(h);
  std::fclose(f);
  return g;
}

// The centre of grid cell (i, j): the normalised mean of its four corners' unit vectors.
void cell_centre(const GridPoints& g, long i, long j, double& lat, double& lon) {
  double v[3] = {0, 0, 0};
  for (long dj = 0; dj <= 1; ++dj)
    for (long di = 0; di <= 1; ++di) {
      const std::size_t k = static_cast<std::size_t>((j + dj) * g.ni + i + di);
      v[0] += std::cos(g.lat[k] * kDeg) * std::cos(g.lon[k] * kDeg);
      v[1] += std::cos(g.lat[k] * kDeg) * std::sin(g.lon[k] * kDeg);
      v[2] += std::sin(g.lat[k] * kDeg);
    }
  lat = std::atan2(v[2], std::hypot(v[0], v[1])) / kDeg;
  lon = std::atan2(v[1], v[0]) / kDeg;
}

// Largest error of the field at the centres of every cell of a projected grid.
double worst_cell_error(const GridField& field, const std::filesystem::path& file, int* cells) {
  const GridPoints g = grid_points(file);
  const long nj = static_cast<long>(g.lat.size()) / g.ni;
  double worst = 0.0;
  *cells = 0;
  for (long j = 0; j + 1 < nj; ++j)
    for (long i = 0; i + 1 < g.ni; ++i) {
      double lat, lon;
      cell_centre(g, i, j, lat, lon);
      const double v = field.at(lat, lon);
      if (std::isnan(v)) return INFINITY;
      worst = std::max(worst, std::abs(v - cover_fraction(lat, lon)));
      ++*cells;
    }
  return worst;
}

TEST(GribGrids, GlobalLatLonWithLongitudes0To360AndSouthToNorthRowsIsSampledExactly) {
  GribTempDir dir;
  const auto file = dir.file("ll.grib2");
  append_grib_message(file, "regular_ll_sfc_grib2",
                      tcc(true, {{"Ni", 180L}, {"Nj", 91L}, {"numberOfDataPoints", 180L * 91L}, {"iDirectionIncrementInDegrees", 2.0},
                                 {"jDirectionIncrementInDegrees", 2.0}, {"jScansPositively", 1L},
                                 {"latitudeOfFirstGridPointInDegrees", -90.0}, {"longitudeOfFirstGridPointInDegrees", 0.0},
                                 {"latitudeOfLastGridPointInDegrees", 90.0}, {"longitudeOfLastGridPointInDegrees", 358.0}}),
                      cover_percent);
  const GribCloudMessage m = only_message(file);
  EXPECT_EQ(m.role.band, CloudBand::Total);
  EXPECT_EQ(m.role.quantity, CloudQuantity::Cover);
  EXPECT_TRUE(m.field.exact());
  EXPECT_TRUE(m.field.global());
  EXPECT_NEAR(m.field.spacing_deg(), 2.0, 1e-9);
  // At grid points the stored value (16-bit packing: ~0.002 % of the range).
  EXPECT_NEAR(m.field.at(20.0, 40.0), cover_fraction(20.0, 40.0), 1e-4);
  EXPECT_NEAR(m.field.at(-44.0, 358.0), cover_fraction(-44.0, -2.0), 1e-4);
  // Between them: bilinear interpolation of a smooth field.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> lat(-90.0, 90.0), lon(-540.0, 540.0);
  for (int i = 0; i < 2000; ++i) {
    const double a = lat(rng), b = lon(rng);
    ASSERT_NEAR(m.field.at(a, b), cover_fraction(a, b), 2e-3) << a << ", " << b;
  }
  // No seam across the antimeridian or at 0/360, and one value at each pole.
  EXPECT_DOUBLE_EQ(m.field.at(10.0, 179.0), m.field.at(10.0, -181.0));
  EXPECT_NEAR(m.field.at(10.0, 179.999), m.field.at(10.0, -179.999), 1e-5);
  EXPECT_NEAR(m.field.at(10.0, 359.999), m.field.at(10.0, 0.0), 1e-5);
  for (double l : {0.0, 77.0, 200.0, -120.0}) {
    EXPECT_NEAR(m.field.at(90.0, l), 0.5, 1e-4);
    EXPECT_NEAR(m.field.at(-90.0, l), 0.5, 1e-4);
  }
}

TEST(GribGrids, RegionalLatLonAcrossTheAntimeridianHasDataOnlyInside) {
  GribTempDir dir;
  const auto file = dir.file("pacific.grib2");
  // 170E to 190E (170W), 50N to 30N (rows north to south), 0.5 degrees.
  append_grib_message(file, "regular_ll_sfc_grib2",
                      tcc(false, {{"Ni", 41L}, {"Nj", 41L}, {"numberOfDataPoints", 41L * 41L}, {"iDirectionIncrementInDegrees", 0.5},
                                  {"jDirectionIncrementInDegrees", 0.5}, {"jScansPositively", 0L},
                                  {"latitudeOfFirstGridPointInDegrees", 50.0}, {"longitudeOfFirstGridPointInDegrees", 170.0},
                                  {"latitudeOfLastGridPointInDegrees", 30.0}, {"longitudeOfLastGridPointInDegrees", 190.0}}),
                      cover_fraction);
  const GribCloudMessage m = only_message(file);
  EXPECT_FALSE(m.field.global());
  for (double lon : {170.0, 175.3, 179.9, 180.0, -179.9, -175.0, -170.0})
    EXPECT_NEAR(m.field.at(40.2, lon), cover_fraction(40.2, lon), 1e-3) << lon;
  EXPECT_NEAR(m.field.at(40.0, 180.0), m.field.at(40.0, -180.0), 1e-9);
  for (auto [la, lo] : {std::pair{40.0, 160.0}, {40.0, -160.0}, {60.0, 180.0}, {20.0, 175.0}})
    EXPECT_TRUE(std::isnan(m.field.at(la, lo))) << la << ", " << lo;
}

TEST(GribGrids, GaussianGridsRegularAndReducedAreSampledExactly) {
  GribTempDir dir;
  for (const char* sample : {"regular_gg_sfc_grib2", "reduced_gg_pl_32_grib2"}) {
    const auto file = dir.file(std::string(sample) + ".grib2");
    append_grib_message(file, sample, tcc(true), cover_percent);
    const GribCloudMessage m = only_message(file);
    EXPECT_TRUE(m.field.exact()) << sample;
    EXPECT_TRUE(m.field.global()) << sample;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> lat(-90.0, 90.0), lon(-180.0, 180.0);
    double worst = 0.0;
    for (int i = 0; i < 4000; ++i) {
      const double a = lat(rng), b = lon(rng);
      worst = std::max(worst, std::abs(m.field.at(a, b) - cover_fraction(a, b)));
    }
    // N32: 2.8 degree spacing; bilinear error of this field <= 0.3 * (2 * 2.8 deg)^2 / 8 ~ 0.004,
    // and the polar caps blend to the rows' mean.
    EXPECT_LT(worst, 0.01) << sample;
    for (double l : {0.0, 90.0, 181.0}) EXPECT_NEAR(m.field.at(90.0, l), m.field.at(90.0, 0.0), 1e-9) << sample;
  }
}

struct ProjectedGrid {
  const char* name;
  const char* sample;
  std::vector<GribKey> keys;
};

class GribProjectedGrids : public testing::TestWithParam<int> {};

std::vector<ProjectedGrid> projected_grids() {
  // Polar stereographic, north pole at the centre of a 41 x 41 grid of 100 km (true at 60N):
  // the first point lies 2000 km west and 2000 km south of the pole in the projection plane,
  // at latitude 2 atan(rho / (R (1 + sin 60))) from the pole (spherical earth R = 6371229 m).
  const double rho = std::hypot(2.0e6, 2.0e6), R = 6371229.0;
  const double lat0 = 90.0 - 2.0 * std::atan(rho / (R * (1.0 + std::sin(60.0 * kDeg)))) / kDeg;
  return {
      {"polar_stereographic", "polar_stereographic_sfc_grib2",
       {{"Nx", 41L}, {"Ny", 41L}, {"numberOfDataPoints", 41L * 41L}, {"DxInMetres", 100000.0}, {"DyInMetres", 100000.0}, {"LaDInDegrees", 60.0},
        {"orientationOfTheGridInDegrees", 0.0}, {"latitudeOfFirstGridPointInDegrees", lat0},
        {"longitudeOfFirstGridPointInDegrees", 315.0}}},
      {"lambert", "GRIB2",
       {{"gridDefinitionTemplateNumber", 30L}, {"Nx", 40L}, {"Ny", 30L}, {"numberOfDataPoints", 40L * 30L}, {"latitudeOfFirstGridPointInDegrees", 40.0},
        {"longitudeOfFirstGridPointInDegrees", 350.0}, {"LaDInDegrees", 50.0}, {"LoVInDegrees", 5.0},
        {"Latin1InDegrees", 50.0}, {"Latin2InDegrees", 50.0}, {"DxInMetres", 25000.0}, {"DyInMetres", 25000.0}}},
      {"rotated_ll", "rotated_ll_sfc_grib2",
       {{"Ni", 41L}, {"Nj", 31L}, {"numberOfDataPoints", 41L * 31L}, {"iDirectionIncrementInDegrees", 0.5}, {"jDirectionIncrementInDegrees", 0.5},
        {"jScansPositively", 1L}, {"latitudeOfFirstGridPointInDegrees", -7.5}, {"longitudeOfFirstGridPointInDegrees", 350.0},
        {"latitudeOfLastGridPointInDegrees", 7.5}, {"longitudeOfLastGridPointInDegrees", 10.0},
        {"latitudeOfSouthernPoleInDegrees", -40.0}, {"longitudeOfSouthernPoleInDegrees", 10.0}}},
  };
}

TEST_P(GribProjectedGrids, AreResampledCloseToTheFieldAndEmptyOutside) {
  const ProjectedGrid grid = projected_grids()[static_cast<std::size_t>(GetParam())];
  GribTempDir dir;
  const auto file = dir.file(std::string(grid.name) + ".grib2");
  append_grib_message(file, grid.sample, tcc(GetParam() % 2 == 0, grid.keys), GetParam() % 2 == 0 ? cover_percent : cover_fraction);
  const GribCloudMessage m = only_message(file);
  EXPECT_FALSE(m.field.exact()) << grid.name;
  int cells = 0;
  const double worst = worst_cell_error(m.field, file, &cells);
  EXPECT_GT(cells, 400) << grid.name;
  std::printf("%s: largest error %.4f over %d cell centres\n", grid.name, worst, cells);
  // The splat averages points within about half a spacing: error ~ gradient * spacing / 2.
  EXPECT_LT(worst, 0.01) << grid.name;
  EXPECT_TRUE(std::isnan(m.field.at(-60.0, 100.0))) << grid.name;
}

INSTANTIATE_TEST_SUITE_P(Grids, GribProjectedGrids, testing::Range(0, 3),
                         [](const testing::TestParamInfo<int>& info) { return std::string(projected_grids()[info.param].name); });

TEST(GribGrids, PolarStereographicAroundThePoleHasOneValueThere) {
  GribTempDir dir;
  const auto file = dir.file("polar.grib2");
  append_grib_message(file, "polar_stereographic_sfc_grib2", tcc(true, projected_grids()[0].keys), cover_percent);
  const GribCloudMessage m = only_message(file);
  for (double lon : {0.0, 45.0, 135.0, 180.0, -100.0}) {
    EXPECT_NEAR(m.field.at(90.0, lon), 0.5, 0.01) << lon;
    EXPECT_NEAR(m.field.at(89.5, lon), cover_fraction(89.5, lon), 0.01) << lon;
  }
}

TEST(GribFields, CoverInPercentAndAsAFractionReadAlike) {
  GribTempDir dir;
  struct Case {
    long param_id;
    bool percent;
    CloudBand band;
  };
  for (const Case& c : {Case{228164, true, CloudBand::Total}, Case{164, false, CloudBand::Total},
                        Case{3073, true, CloudBand::Low}, Case{186, false, CloudBand::Low},
                        Case{3074, true, CloudBand::Middle}, Case{187, false, CloudBand::Middle},
                        Case{3075, true, CloudBand::High}, Case{188, false, CloudBand::High}}) {
    const auto file = dir.file("p" + std::to_string(c.param_id) + ".grib2");
    append_grib_message(file, "regular_ll_sfc_grib2", {{"paramId", c.param_id}},
                        c.percent ? cover_percent : cover_fraction);
    const GribCloudMessage m = only_message(file);
    EXPECT_EQ(m.role.band, c.band) << c.param_id;
    EXPECT_NEAR(m.field.at(30.0, 10.0), cover_fraction(30.0, 10.0), 1e-4) << c.param_id;
  }
}

TEST(GribFields, MissingValuesOfABitmapAreLeftOut) {
  GribTempDir dir;
  const auto file = dir.file("bitmap.grib2");
  // The sample: 16 x 31 points, 0..30 E, 60..0 N, 2 degrees. No values north of 40N.
  append_grib_message(file, "regular_ll_sfc_grib2", tcc(true), [](double lat, double lon) {
    return lat > 40.0 ? NAN : cover_percent(lat, lon);
  });
  const GribCloudMessage m = only_message(file);
  EXPECT_NEAR(m.field.at(20.0, 11.0), cover_fraction(20.0, 11.0), 2e-3);
  // Between the last row with values (40N) and the first without: the row with values.
  EXPECT_NEAR(m.field.at(41.0, 10.0), cover_fraction(40.0, 10.0), 1e-4);
  EXPECT_TRUE(std::isnan(m.field.at(50.0, 10.0)));
}


TEST(GribFields, BasesAndTopsInPressureGeopotentialAndHeightBecomeAltitudes) {
  GribTempDir dir;
  const auto file = dir.file("bands.grib2");
  append_cloud_field(file, 6, 1, 214, 40.0, 12);               // low cloud cover, %
  append_cloud_field(file, 3, 0, 212, 90000.0, 12);            // low cloud bottom, Pa
  append_cloud_field(file, 3, 5, 213, 1500.0, 12);             // low cloud top, gpm
  append_cloud_field(file, 6, 1, 224, 30.0, 12);               // middle cloud cover
  append_cloud_field(file, 3, 4, 222, 3000.0 * kStandardGravity_mps2, 12);  // middle cloud bottom, m2/s2
  append_cloud_field(file, 3, 6, 223, 4200.0, 12);             // middle cloud top, geometric m
  append_cloud_field(file, 0, 0, 213, 270.0, 12);              // temperature at the low cloud top: ignored
  const GribReadResult r = read_grib_cloud_fields(file.string());
  EXPECT_EQ(r.messages, 7);
  EXPECT_EQ(r.clouds.size(), 6u);
  ASSERT_EQ(r.ignored.size(), 1u);
  const GriddedWeather w = GriddedWeather::from_messages(r.clouds, "bands");
  const std::vector<CloudLayer> layers = w.layers_at(30.0, 10.0, 0.0);
  ASSERT_EQ(layers.size(), 2u);
  EXPECT_EQ(layers[0].type, CloudType::Stratocumulus);
  EXPECT_NEAR(layers[0].coverage, 0.4, 1e-4);
  EXPECT_NEAR(layers[0].base_m, standard_pressure_altitude_m(90000.0), 0.5);
  EXPECT_NEAR(layers[0].top_m, geometric_from_geopotential_m(1500.0), 0.5);
  EXPECT_EQ(layers[1].type, CloudType::Altocumulus);
  EXPECT_NEAR(layers[1].base_m, geometric_from_geopotential_m(3000.0), 0.5);
  EXPECT_NEAR(layers[1].top_m, 4200.0, 0.5);
}

TEST(GribFields, ForecastStepsBlendLinearlyInTime) {
  GribTempDir dir;
  const auto file = dir.file("steps.grib2");
  append_cloud_field(file, 6, 1, 214, 20.0, 6);   // valid 06 UTC
  append_cloud_field(file, 6, 1, 214, 60.0, 12);  // valid 12 UTC
  const GriddedWeather w = GriddedWeather::load_grib({file.string()});
  const std::vector<double> t = w.valid_times();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_DOUBLE_EQ(t[1] - t[0], 6 * 3600.0);
  EXPECT_NEAR(w.column_at(30.0, 10.0, t[0] + 3 * 3600.0)[CloudBand::Low].cover, 0.4, 1e-4);
  EXPECT_NEAR(w.column_at(30.0, 10.0, t[0] - 86400.0)[CloudBand::Low].cover, 0.2, 1e-4);
  EXPECT_NEAR(w.column_at(30.0, 10.0, t[1] + 86400.0)[CloudBand::Low].cover, 0.6, 1e-4);
  EXPECT_NEAR(w.column_at(30.0, 10.0, NAN)[CloudBand::Low].cover, 0.2, 1e-4);
}

TEST(GribFields, CloudCoverOnPressureLevelsFillsTheBands) {
  GribTempDir dir;
  const auto file = dir.file("levels.grib2");
  // ECMWF cc (0/6/32, fraction) on 1000-300 hPa; cloud at 850 and 700 hPa only... 850 is
  // low (below sigma 0.8), 700 middle.
  for (long hPa : {1000L, 925L, 850L, 700L, 500L, 300L}) {
    const double cover = hPa == 850 ? 0.6 : hPa == 700 ? 0.3 : 0.0;
    append_grib_message(file, "regular_ll_pl_grib2",
                        {{"paramId", 248L}, {"level", hPa}, {"dataDate", 20260601L}, {"dataTime", 1200L}},
                        [cover](double, double) { return cover; });
  }
  const GriddedWeather w = GriddedWeather::load_grib({file.string()});
  const CloudColumn c = w.column_at(30.0, 10.0, 0.0);
  EXPECT_NEAR(c[CloudBand::Low].cover, 0.6, 1e-3);
  EXPECT_NEAR(c[CloudBand::Middle].cover, 0.3, 1e-3);
  EXPECT_NEAR(c[CloudBand::High].cover, 0.0, 1e-3);
  const double z850 = standard_pressure_altitude_m(85000.0);
  EXPECT_NEAR(c[CloudBand::Low].base_m, z850 - 0.5 * (z850 - standard_pressure_altitude_m(92500.0)), 1.0);
}

// The one-line error of reading `file`, or "" when it reads.
std::string read_error(const std::filesystem::path& file) {
  try {
    read_grib_cloud_fields(file.string());
  } catch (const WeatherFileError& e) {
    return e.what();
  }
  return "";
}

TEST(GribErrors, BadFilesGetOneLineNamingTheFileAndTheProblem) {
  GribTempDir dir;
  const auto text = dir.file("notes.grib2");
  std::ofstream(text) << "METAR LSZH 051150Z 24008KT 9999 FEW030 BKN080 05/01 Q1021\n";
  EXPECT_EQ(read_error(text), text.string() + ": not a GRIB file (no GRIB message found)");

  EXPECT_NE(read_error(dir.file("absent.grib2")).find("cannot open: No such file"), std::string::npos);

  const auto good = dir.file("good.grib2");
  append_grib_message(good, "regular_ll_sfc_grib2", tcc(true), cover_percent);
  append_grib_message(good, "regular_ll_sfc_grib2", tcc(true), cover_percent);
  const auto size = std::filesystem::file_size(good);
  std::vector<char> bytes(size);
  std::ifstream(good, std::ios::binary).read(bytes.data(), static_cast<std::streamsize>(size));
  const auto cut = dir.file("cut.grib2");
  std::ofstream(cut, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(size * 3 / 4));
  const std::string truncated = read_error(cut);
  EXPECT_EQ(truncated.rfind(cut.string() + ": truncated or damaged GRIB message 2 after byte " + std::to_string(size / 2), 0), 0u)
      << truncated;

  const auto grib1 = dir.file("old.grib");
  append_grib_message(grib1, "GRIB1", {}, cover_percent);
  EXPECT_NE(read_error(grib1).find("GRIB edition 1 is not supported"), std::string::npos) << read_error(grib1);

  const auto temperature = dir.file("t.grib2");
  append_grib_message(temperature, "regular_ll_sfc_grib2", {{"paramId", 130L}}, [](double, double) { return 280.0; });
  const std::string none = read_error(temperature);
  EXPECT_EQ(none.rfind(temperature.string() + ": no cloud fields among its 1 GRIB messages (", 0), 0u) << none;
  EXPECT_NE(none.find("expected cloud cover (e.g. tcc, lcc, mcc, hcc)"), std::string::npos) << none;

  // A data section that does not hold what section 5 says (four times the groups): ecCodes'
  // complex-packing decoder fails a consistency check, which would abort the process; the
  // reader names the message instead, and reads other files afterwards.
  const auto packed = dir.file("complex.grib2");
  append_grib_message(packed, "regular_ll_sfc_grib2",
                      {{"paramId", 164L}, {"bitsPerValue", 12L},
                       {"packingType", std::string("grid_complex_spatial_differencing")}},
                      cover_fraction);
  std::vector<char> message(std::filesystem::file_size(packed));
  std::ifstream(packed, std::ios::binary).read(message.data(), static_cast<std::streamsize>(message.size()));
  const auto octets = [&](std::size_t at) {  // 4-byte big-endian number at `at`
    std::uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(message[at + k]);
    return v;
  };
  bool damaged_groups = false;
  for (std::size_t at = 16; at + 35 < message.size() && octets(at) > 0; at += octets(at)) {  // sections after the indicator
    if (message[at + 4] != 5) continue;
    const std::uint32_t groups = octets(at + 31);  // octets 32-35 of template 5.2 / 5.3: the number of groups
    for (int k = 0; k < 4; ++k) message[at + 31 + k] = static_cast<char>(((4 * groups) >> (24 - 8 * k)) & 0xff);
    damaged_groups = groups > 0;
    break;
  }
  ASSERT_TRUE(damaged_groups);
  const auto damaged = dir.file("damaged.grib2");
  std::ofstream(damaged, std::ios::binary).write(message.data(), static_cast<std::streamsize>(message.size()));
  const std::string damage = read_error(damaged);
  EXPECT_EQ(damage.rfind(damaged.string() + ": message 1 (tcc, entireAtmosphere): cannot decode values packed as "
                         "'grid_complex_spatial_differencing': the data section is damaged (", 0), 0u)
      << damage;
  EXPECT_EQ(read_error(packed), "") << "a good file reads after a damaged one";

  // A local cover parameter in units that are neither % nor a fraction.
  std::string problem;
  const auto role = classify_cloud_field(GribIdentity{0, 6, 192, 1, 164, "tcc", "okta"}, &problem);
  EXPECT_TRUE(role.has_value());
  EXPECT_EQ(problem, "cloud cover in units 'okta', neither % nor a fraction 0-1");
  problem.clear();
  classify_cloud_field(GribIdentity{0, 6, 192, 1, 164, "tcc", "(0 - 1)"}, &problem);
  EXPECT_EQ(problem, "");

  const auto spectral = dir.file("sh.grib2");
  append_grib_message(spectral, "sh_sfc_grib2", {{"paramId", 164L}}, [](double, double) { return 0.5; });
  const std::string sh = read_error(spectral);
  EXPECT_NE(sh.find("grid 'sh' cannot be geolocated"), std::string::npos) << sh;
}

}  // namespace
