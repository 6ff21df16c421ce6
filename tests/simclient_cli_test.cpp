// The pieces of the sim_client command line that need no service: sweep files (JSON
// poses, grids, CSV, errors), frame statistics on a synthetic EXR, weather-map tiles,
// progress text, manifest rows, weather-map flag values, replay poses and watch counters.
// The flag value parsers shared with cloudsvc are tested in option_values_test.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "forecast_test_support.h"
#include "common/option_values.h"
#include "protocol/validate.h"
#include "protocol/weather_conversion.h"
#include "sim_client/commands.h"
#include "sim_client/contact_sheet.h"
#include "sim_client/forecast_raster.h"
#include "sim_client/image_stats.h"
#include "sim_client/manifest.h"
#include "sim_client/map_flags.h"
#include "sim_client/map_image.h"
#include "sim_client/map_tiles.h"
#include "sim_client/progress.h"
#include "sim_client/replay_poses.h"
#include "sim_client/run_summary.h"
#include "sim_client/sweep_plan.h"
#include "sim_client/usage_errors.h"
#include "sim_client/watch_stats.h"
#include "weather/forecast_frame.h"
#include "weather/weather_timeline.h"

namespace cloudsvc::sim {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test, removed afterwards.
class TempDir {
 public:
  explicit TempDir(const std::string& tag)
      : path_(fs::temp_directory_path() / ("simclient_cli_" + tag + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// The UsageError or cli::FlagError message of f(), or "" when it throws neither.
template <class F>
std::string usage_error(F&& f) {
  try {
    f();
  } catch (const UsageError& e) {
    return e.what();
  } catch (const cli::FlagError& e) {
    return e.what();
  }
  return "";
}

// ---- sweep files: JSON poses ------------------------------------------------------------

TEST(SweepJson, PosesTakeDefaultsFromTheTopLevelAndOverrideThem) {
  const SweepPlan plan = parse_sweep_json(R"({
      "time": "2026-06-21T12:00:00Z", "weather": "broken-cumulus",
      "poses": [
        {"lat": 47.45, "lon": 8.56, "alt": 2500},
        {"lat": -33.9, "lon": 151.2, "alt": 1200, "heading": 90, "pitch": -5, "roll": 10,
         "time": 1718000000, "weather": "clear"},
        {"lat": 0, "lon": 0, "alt": 0, "time": "2026-06-21T13:30:00+01:00", "weather": "broken-cumulus"}]})",
                                          "s.json", ".");
  ASSERT_EQ(plan.entries.size(), 3u);
  const SweepEntry& a = plan.entries[0];
  EXPECT_EQ(a.lat_deg, 47.45);
  EXPECT_EQ(a.lon_deg, 8.56);
  EXPECT_EQ(a.alt_m, 2500.0);
  EXPECT_EQ(a.heading_deg, 0.0);
  EXPECT_EQ(a.pitch_deg, 0.0);
  EXPECT_EQ(a.roll_deg, 0.0);
  EXPECT_EQ(a.utc_unix_s, 1782043200.0);  // 2026-06-21T12:00:00Z
  const SweepEntry& b = plan.entries[1];
  EXPECT_EQ(b.heading_deg, 90.0);
  EXPECT_EQ(b.pitch_deg, -5.0);
  EXPECT_EQ(b.roll_deg, 10.0);
  EXPECT_EQ(b.utc_unix_s, 1718000000.0);
  EXPECT_EQ(plan.entries[2].utc_unix_s, 1782043200.0 + 1800.0);  // 12:30Z
  // Two distinct weathers; the repeated preset is shared.
  ASSERT_EQ(plan.weathers.size(), 2u);
  ASSERT_TRUE(a.weather && b.weather && plan.entries[2].weather);
  EXPECT_EQ(*a.weather, *plan.entries[2].weather);
  EXPECT_NE(*a.weather, *b.weather);
  EXPECT_EQ(plan.weathers[*a.weather].label, "broken-cumulus");
  EXPECT_EQ(plan.weathers[*b.weather].label, "clear");
  EXPECT_TRUE(plan.weathers[*b.weather].weather.layers.empty());
}

TEST(SweepJson, WithoutWeatherTheEntriesLeaveTheServiceWeatherAlone) {
  const SweepPlan plan = parse_sweep_json(R"({"poses": [{"lat": 1, "lon": 2, "alt": 3}]})", "s.json", ".");
  ASSERT_EQ(plan.entries.size(), 1u);
  EXPECT_FALSE(plan.entries[0].weather.has_value());
  EXPECT_TRUE(plan.weathers.empty());
  EXPECT_EQ(plan.entries[0].utc_unix_s, kDefaultSweepTime_s);
}

TEST(SweepJson, WeatherMayBeInlineOrAFileNextToTheSweep) {
  TempDir dir("weatherfile");
  {
    std::ofstream f(dir.path() / "deck.json");
    f << R"({"name": "my deck", "layers": [{"type": "stratocumulus", "base_m": 1200, "top_m": 1800, "coverage": 0.9}]})";
  }
  const SweepPlan plan = parse_sweep_json(R"({"poses": [
      {"lat": 1, "lon": 2, "alt": 3, "weather": "deck.json"},
      {"lat": 1, "lon": 2, "alt": 3, "weather": {"name": "thin", "layers": [{"type": "cu", "base_m": 1000, "top_m": 2000, "coverage": 0.1}]}}]})",
                                          "s.json", dir.path());
  ASSERT_EQ(plan.weathers.size(), 2u);
  EXPECT_EQ(plan.weathers[0].label, "deck.json");
  ASSERT_EQ(plan.weathers[0].weather.layers.size(), 1u);
  EXPECT_EQ(plan.weathers[0].weather.layers[0].coverage, 0.9);
  EXPECT_EQ(plan.weathers[1].label, "thin");
  EXPECT_EQ(plan.weathers[1].weather.layers[0].coverage, 0.1);
}

// ---- sweep files: grids -------------------------------------------------------------------

TEST(SweepJson, GridIsEveryCombinationWithLatitudeOutermostAndExactEnds) {
  const SweepPlan plan = parse_sweep_json(R"({
      "grid": {"lat": [47.0, 48.0, 3], "lon": 8.5, "alt": [1000, 3000, 2], "heading": [0, 270, 4], "pitch": 5},
      "time": "2026-03-01T06:00:00Z", "weather": "overcast-stratus"})",
                                          "g.json", ".");
  ASSERT_EQ(plan.entries.size(), 3u * 2u * 4u);
  ASSERT_EQ(plan.weathers.size(), 1u);
  std::set<double> lats, alts, headings;
  for (const SweepEntry& e : plan.entries) {
    lats.insert(e.lat_deg);
    alts.insert(e.alt_m);
    headings.insert(e.heading_deg);
    EXPECT_EQ(e.lon_deg, 8.5);
    EXPECT_EQ(e.pitch_deg, 5.0);
    EXPECT_EQ(e.roll_deg, 0.0);
    EXPECT_EQ(e.utc_unix_s, 1772344800.0);  // 2026-03-01T06:00:00Z
    EXPECT_EQ(e.weather, std::optional<std::size_t>(0));
  }
  EXPECT_EQ(lats, (std::set<double>{47.0, 47.5, 48.0}));
  EXPECT_EQ(alts, (std::set<double>{1000.0, 3000.0}));
  EXPECT_EQ(headings, (std::set<double>{0.0, 90.0, 180.0, 270.0}));
  // Order: heading varies fastest, then alt, then lat.
  EXPECT_EQ(plan.entries[0].heading_deg, 0.0);
  EXPECT_EQ(plan.entries[1].heading_deg, 90.0);
  EXPECT_EQ(plan.entries[3].heading_deg, 270.0);
  EXPECT_EQ(plan.entries[4].alt_m, 3000.0);
  EXPECT_EQ(plan.entries[4].heading_deg, 0.0);
  EXPECT_EQ(plan.entries[8].lat_deg, 47.5);
  EXPECT_EQ(plan.entries.back().lat_deg, 48.0);
  EXPECT_EQ(plan.entries.back().origin, "grid[23]");
}

TEST(SweepJson, GridAxisWithCountOneIsItsFirstValue) {
  const SweepPlan plan = parse_sweep_json(R"({"grid": {"lat": [10, 20, 1], "lon": 0, "alt": 500}})", "g.json", ".");
  ASSERT_EQ(plan.entries.size(), 1u);
  EXPECT_EQ(plan.entries[0].lat_deg, 10.0);
}

// ---- sweep files: errors name the file and the field or line ------------------------------

TEST(SweepJson, ErrorsNameTheFileAndTheField) {
  auto err = [](const std::string& text) { return usage_error([&] { parse_sweep_json(text, "s.json", "."); }); };
  EXPECT_EQ(err(R"({"poses": [{"lat": 1, "lon": 2, "alt": 3}, {"lat": 95, "lon": 2, "alt": 3}]})"),
            "s.json: poses[1].lat: 95 out of range [-90, 90] (degrees)");
  EXPECT_EQ(err(R"({"poses": [{"lat": 1, "lon": 2}]})"), "s.json: poses[0].alt: missing (required)");
  EXPECT_EQ(err(R"({"poses": [{"lat": 1, "lon": 2, "alt": 3, "hdg": 4}]})"),
            "s.json: poses[0].hdg: unknown key (expected lat, lon, alt, heading, pitch, roll, time, weather)");
  EXPECT_EQ(err(R"({"poses": [{"lat": "47", "lon": 2, "alt": 3}]})"),
            "s.json: poses[0].lat: expected a number, got string \"47\"");
  EXPECT_EQ(err(R"({"poses": [{"lat": 1, "lon": 2, "alt": 200000}]})"),
            "s.json: poses[0].alt: 200000 out of range [-500, 100000] (metres above the WGS84 ellipsoid)");
  EXPECT_EQ(err(R"({"poses": []})"), "s.json: poses: expected a non-empty array of pose objects");
  EXPECT_EQ(err(R"({"poses": [], "grid": {}})"), "s.json: (top level): expected exactly one of \"poses\" and \"grid\"");
  EXPECT_EQ(err(R"({"grid": {"lat": [1, 2, 0], "lon": 0, "alt": 0}})"),
            "s.json: grid.lat[2]: count must be an integer in [1, 100000] written without a fraction or exponent "
            "(3, not 3.0 or 3e0), got 0");
  // 1.0 is a whole number: the message had said "must be a whole number ..., got 1.0".
  EXPECT_EQ(err(R"({"grid": {"lat": [1, 2, 1.0], "lon": 0, "alt": 0}})"),
            "s.json: grid.lat[2]: count must be an integer in [1, 100000] written without a fraction or exponent "
            "(3, not 3.0 or 3e0), got 1.0");
  EXPECT_EQ(err(R"({"grid": {"lat": [1, 2], "lon": 0, "alt": 0}})"),
            "s.json: grid.lat: expected a number or [first, last, count]");
  // 300,000 nested arrays as a latitude: used to overflow the stack while the error
  // message serialised the value (json::dump recurses per level).
  const std::string deep = std::string(300000, '[') + std::string(300000, ']');
  EXPECT_EQ(err(R"({"poses": [{"lat": )" + deep + R"(, "lon": 2, "alt": 3}]})"),
            "s.json: (top level): nested more than 32 levels deep");
  EXPECT_EQ(err(R"({"grid": {"lat": [0, 1, 1000], "lon": [0, 1, 1000], "alt": 0}})"),
            "s.json: grid: has 1000000 combinations, at most 100000");
  EXPECT_EQ(err(R"({"time": "yesterday", "poses": [{"lat": 1, "lon": 2, "alt": 3}]})"),
            "s.json: time: malformed time \"yesterday\": expected ISO 8601 UTC, e.g. 2026-06-21T12:00:00Z");
  const std::string unknown = err(R"({"weather": "fog", "poses": [{"lat": 1, "lon": 2, "alt": 3}]})");
  EXPECT_EQ(unknown.rfind("s.json: weather: unknown weather 'fog' (a preset: clear, ", 0), 0u) << unknown;
  const std::string bad_layer = err(R"({"weather": {"layers": [{"type": "cu", "base_m": 1000, "top_m": 900, "coverage": 0.5}]},
                                        "poses": [{"lat": 1, "lon": 2, "alt": 3}]})");
  EXPECT_NE(bad_layer.find("s.json: weather"), std::string::npos) << bad_layer;
  EXPECT_NE(bad_layer.find("layers[0].top_m"), std::string::npos) << bad_layer;
  const std::string syntax = err(R"({"poses": [)");
  EXPECT_EQ(syntax.rfind("s.json: ", 0), 0u);
  EXPECT_NE(syntax.find("syntax error"), std::string::npos) << syntax;
  EXPECT_EQ(syntax.find('\n'), std::string::npos);
}

// ---- sweep files: CSV ---------------------------------------------------------------------

TEST(SweepCsv, RowsMayRepeatTimesAndCarryAWeatherColumn) {
  const SweepPlan plan = parse_sweep_csv(
      "# views over Zurich\n"
      "Weather, time,lat,lon,alt,heading,pitch,roll\n"
      "clear,2026-06-21T12:00:00Z,47.45,8.56,2500,270,5,0\n"
      "\n"
      "overcast-stratus,2026-06-21T12:00:00Z,47.45,8.56,2500,270,5,0\n"
      ",1782043200,47.45,8.56,300,90,20,-10\n",
      "s.csv", ".");
  ASSERT_EQ(plan.entries.size(), 3u);
  ASSERT_EQ(plan.weathers.size(), 2u);
  EXPECT_EQ(plan.weathers[*plan.entries[0].weather].label, "clear");
  EXPECT_EQ(plan.weathers[*plan.entries[1].weather].label, "overcast-stratus");
  EXPECT_FALSE(plan.entries[2].weather.has_value());  // empty cell: unchanged
  EXPECT_EQ(plan.entries[2].utc_unix_s, plan.entries[0].utc_unix_s);
  EXPECT_EQ(plan.entries[2].roll_deg, -10.0);
  EXPECT_EQ(plan.entries[2].origin, "line 6");
}

TEST(SweepCsv, WeatherColumnIsOptional) {
  const SweepPlan plan = parse_sweep_csv("time,lat,lon,alt,heading,pitch,roll\n0,1,2,3,4,5,6\n", "s.csv", ".");
  ASSERT_EQ(plan.entries.size(), 1u);
  EXPECT_FALSE(plan.entries[0].weather.has_value());
  EXPECT_EQ(plan.entries[0].utc_unix_s, 0.0);
}

TEST(SweepCsv, ErrorsNameFileAndLine) {
  auto err = [](const std::string& text) { return usage_error([&] { parse_sweep_csv(text, "s.csv", "."); }); };
  EXPECT_EQ(err("time,lat,lon,alt,heading,pitch\n"),
            "s.csv:1: header lacks column roll (required: time,lat,lon,alt,heading,pitch,roll; optional: weather)");
  EXPECT_EQ(err("time,lat,lon,alt,heading,pitch,roll\n0,1,2,3,4,5,6\n0,1,x,3,4,5,6\n"),
            "s.csv:3: malformed lon 'x': expected a number");
  EXPECT_EQ(err("time,lat,lon,alt,heading,pitch,roll\n0,-91,2,3,4,5,6\n"),
            "s.csv:2: lat: -91 out of range [-90, 90] (degrees)");
  EXPECT_EQ(err("time,lat,lon,alt,heading,pitch,roll\n0,1,2,3,4,5\n"), "s.csv:2: row has 6 fields, the header has 7");
  EXPECT_EQ(err("time,lat,lon,alt,heading,pitch,roll\nnoon,1,2,3,4,5,6\n"),
            "s.csv:2: malformed time 'noon': expected ISO 8601 UTC or seconds since the Unix epoch");
  EXPECT_EQ(err("time,lat,lon,alt,heading,pitch,roll\n"), "s.csv:1: no data row after the header");
  EXPECT_EQ(err("time,lat,lon,alt,heading,pitch,roll,weather\n0,1,2,3,4,5,6,fog\n")
                .rfind("s.csv:2: unknown weather 'fog'", 0),
            0u);
}

TEST(SweepFile, LoadDispatchesOnTheExtension) {
  TempDir dir("load");
  const fs::path csv = dir.path() / "S.CSV";
  {
    std::ofstream(csv) << "time,lat,lon,alt,heading,pitch,roll\n0,1,2,3,4,5,6\n";
  }
  EXPECT_EQ(load_sweep(csv.string()).entries.size(), 1u);
  EXPECT_EQ(usage_error([&] { load_sweep((dir.path() / "s.txt").string()); }),
            (dir.path() / "s.txt").string() + ": unsupported sweep file (expected .json or .csv)");
  EXPECT_EQ(usage_error([&] { load_sweep((dir.path() / "absent.json").string()); }),
            (dir.path() / "absent.json").string() + ": cannot open");
}

// ---- image statistics ---------------------------------------------------------------------

// A 4x2 RGBA float EXR with known values (all exactly representable in half float).
TEST(ImageStats, SyntheticExrGivesExactMeanFractionAndNonFiniteCount) {
  TempDir dir("stats");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  // Luminances: grey pixels have Y = value; the NaN and Inf pixels are excluded.
  const std::vector<float> px = {
      1.0f, 1.0f, 1.0f, 0.0f,   0.5f, 0.5f, 0.5f, 1.0f,   2.0f, 2.0f, 2.0f, 0.5f,  0.25f, 0.25f, 0.25f, 0.005f,
      nan,  0.0f, 0.0f, 1.0f,   0.0f, inf,  0.0f, 1.0f,   0.0f, 0.0f, 0.0f, 0.02f, 1.0f,  0.0f,  0.0f,  0.0f,
  };
  const ImageStats direct = compute_image_stats(px, 4, 2, 4);
  const double mean = (1.0 + 0.5 + 2.0 + 0.25 + 0.0 + 0.2126) / 6.0;
  EXPECT_NEAR(direct.mean_radiance, mean, 1e-12);
  EXPECT_EQ(direct.nonfinite, 2u);
  EXPECT_TRUE(direct.has_alpha);
  // alpha > 0.01 among finite pixels: 1.0, 0.5, 0.02 -> 3 of 8.
  EXPECT_DOUBLE_EQ(direct.cloud_fraction, 3.0 / 8.0);

  const fs::path exr = dir.path() / "frame.exr";
  OIIO::ImageSpec spec(4, 2, 4, OIIO::TypeDesc::HALF);
  spec.channelnames = {"R", "G", "B", "A"};
  OIIO::ImageBuf buf(spec);
  ASSERT_TRUE(buf.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, px.data()));
  ASSERT_TRUE(buf.write(exr.string()));
  const ImageStats read = read_image_stats(exr.string());
  EXPECT_EQ(read.width, 4);
  EXPECT_EQ(read.height, 2);
  EXPECT_EQ(read.nonfinite, 2u);
  EXPECT_DOUBLE_EQ(read.cloud_fraction, 3.0 / 8.0);
  // 0.2126 R of the last pixel: R = 1 exactly in half; the weights are applied in double.
  EXPECT_NEAR(read.mean_radiance, mean, 1e-9);
}

TEST(ImageStats, RgbWithoutAlphaHasNoCloudFraction) {
  const ImageStats s = compute_image_stats({0.1f, 0.2f, 0.3f}, 1, 1, 3);
  EXPECT_FALSE(s.has_alpha);
  EXPECT_EQ(s.cloud_fraction, 0.0);
  EXPECT_NEAR(s.mean_radiance, 0.2126 * 0.1 + 0.7152 * 0.2 + 0.0722 * 0.3, 1e-7);
  EXPECT_THROW(compute_image_stats({0.1f, 0.2f}, 1, 1, 3), std::invalid_argument);
  EXPECT_THROW(read_image_stats("/nonexistent/frame.exr"), std::runtime_error);
}

// ---- weather-map tiles ---------------------------------------------------------------------

// Raster value of texel (x, y) (image order, y = 0 north) and channel k: unique per texel.
float texel_value(int x, int y, int k) { return static_cast<float>((x + 3000 * y) % 997) / 996.0f * (k ? 0.5f : 1.0f); }

MapRaster make_raster(int w, int h, std::vector<std::uint8_t> bits) {
  MapRaster r;
  r.width = w;
  r.height = h;
  r.channel_bits = std::move(bits);
  const std::size_t nc = r.channel_bits.size();
  r.values.resize(static_cast<std::size_t>(w) * h * nc);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (std::size_t k = 0; k < nc; ++k)
        r.values[(static_cast<std::size_t>(y) * w + x) * nc + k] = texel_value(x, y, static_cast<int>(k));
  return r;
}

TEST(MapTiles, A3000x1500MapSplitsIntoTilesOfAtMost1024CoveringTheBoundsExactly) {
  // Raster channel 0 = density, channel 1 = coverage: the tiles must reorder to ascending bits.
  const MapRaster raster =
      make_raster(3000, 1500, {protocol::tile_channel::kDensity, protocol::tile_channel::kCoverage});
  const GeoBounds bounds{40.0, 0.0, 50.0, 20.0};
  const auto tiles = split_into_tiles(raster, bounds, 1782043200.0, 1024);
  ASSERT_EQ(tiles.size(), 6u);  // 3 columns x 2 rows

  std::uint64_t texels = 0;
  std::set<double> lon_edges, lat_edges;
  for (const auto& t : tiles) {
    EXPECT_LE(t.width, 1024u);
    EXPECT_LE(t.height, 1024u);
    EXPECT_EQ(t.width, 1000u);
    EXPECT_EQ(t.height, 750u);
    EXPECT_EQ(t.channels, protocol::tile_channel::kCoverage | protocol::tile_channel::kDensity);
    EXPECT_EQ(t.valid_at_utc_s, 1782043200.0);
    EXPECT_EQ(t.data.size(), static_cast<std::size_t>(t.width) * t.height * 2);
    EXPECT_FALSE(protocol::validate(protocol::Message(t)).has_value());
    texels += static_cast<std::uint64_t>(t.width) * t.height;
    lon_edges.insert(t.lon_min_deg);
    lon_edges.insert(t.lon_max_deg);
    lat_edges.insert(t.lat_min_deg);
    lat_edges.insert(t.lat_max_deg);
  }
  EXPECT_EQ(texels, 3000u * 1500u);
  // Shared edges are bit-identical: 4 distinct longitudes and 3 latitudes, the outer ones
  // exactly the bounds.
  EXPECT_EQ(lon_edges, (std::set<double>{0.0, 20.0 / 3.0, 40.0 / 3.0, 20.0}));
  EXPECT_EQ(lat_edges, (std::set<double>{40.0, 45.0, 50.0}));
  // Every tile abuts its neighbours: the areas sum to the bounds' area.
  double area = 0.0;
  for (const auto& t : tiles) area += (t.lat_max_deg - t.lat_min_deg) * (t.lon_max_deg - t.lon_min_deg);
  EXPECT_NEAR(area, 10.0 * 20.0, 1e-9);

  // Tile 0 is the south-west one: its row 0 is the raster's bottom row (y = 1499).
  const auto& sw = tiles[0];
  EXPECT_EQ(sw.lat_min_deg, 40.0);
  EXPECT_EQ(sw.lon_min_deg, 0.0);
  for (auto [col, row] : {std::pair{0, 0}, std::pair{999, 749}, std::pair{17, 300}}) {
    const std::size_t i = (static_cast<std::size_t>(row) * sw.width + col) * 2;
    const int y = 1499 - row;
    EXPECT_EQ(sw.data[i + 0], texel_value(col, y, 1)) << "coverage first (raster channel 1)";
    EXPECT_EQ(sw.data[i + 1], texel_value(col, y, 0)) << "density second (raster channel 0)";
  }
  // Tile 5 is the north-east one: its last row is the raster's top row (y = 0).
  const auto& ne = tiles[5];
  EXPECT_EQ(ne.lat_max_deg, 50.0);
  EXPECT_EQ(ne.lon_max_deg, 20.0);
  const std::size_t last = (static_cast<std::size_t>(749) * ne.width + 999) * 2;
  EXPECT_EQ(ne.data[last], texel_value(2999, 0, 1));
}

TEST(MapTiles, TilesEastOfTheAntimeridianAreShiftedIntoTheProtocolRange) {
  const MapRaster raster = make_raster(2048, 4, {protocol::tile_channel::kCoverage});
  const auto tiles = split_into_tiles(raster, GeoBounds{-10.0, 170.0, 10.0, 190.0}, 0.0, 1024);
  ASSERT_EQ(tiles.size(), 2u);
  EXPECT_EQ(tiles[0].lon_min_deg, 170.0);
  EXPECT_EQ(tiles[0].lon_max_deg, 180.0);
  EXPECT_EQ(tiles[1].lon_min_deg, -180.0);
  EXPECT_EQ(tiles[1].lon_max_deg, -170.0);
  for (const auto& t : tiles) EXPECT_FALSE(protocol::validate(protocol::Message(t)).has_value());
}

TEST(MapTiles, TileSideRespectsTheServiceLimits) {
  protocol::Limits limits = protocol::protocol_limits();
  EXPECT_EQ(tile_side_for(limits, 4), 1024u);
  limits.max_tile_size = 300;
  EXPECT_EQ(tile_side_for(limits, 1), 300u);
  limits.max_tile_size = 1024;
  limits.max_payload_bytes = 1u << 20;  // 1 MiB: (1048576 - 1024 B) / 16 B per texel = 255.9^2
  EXPECT_EQ(tile_side_for(limits, 4), 255u);
  EXPECT_THROW(split_into_tiles(make_raster(2, 2, {1, 1}), GeoBounds{0, 0, 1, 1}, 0.0, 16), std::invalid_argument);
}

// A forecast whose low band covers a latitude-dependent fraction of the sky east of 0°
// (none west of it), its mid band 0.3 everywhere.
const test::FunctionForecast banded_forecast("banded", [](double lat_deg, double lon_deg) {
  weather::CloudColumn c;
  c[weather::CloudBand::Low] = {lon_deg >= 0.0 ? 0.5 + 0.5 * std::sin(lat_deg * M_PI / 180.0) : 0.0, 800.0, 1600.0};
  c[weather::CloudBand::Middle] = {0.3, 4000.0, 5000.0};
  return c;
}, 1780272000.0);

// `sim_client weather --grib` sends each step as forecast_raster tiles: applied to the
// service's map they give the map the service itself makes of the forecast (forecast_map),
// texel for texel, when the sizes match.
TEST(ForecastTiles, ApplyToTheMapTheServiceMakesOfTheForecast) {
  const auto& f = banded_forecast;
  const MapRaster raster = forecast_raster(f, 1780272000.0, 64, 32);
  ASSERT_EQ(raster.value_count(), 8u);
  const auto tiles = split_into_tiles(raster, GeoBounds{-90.0, -180.0, 90.0, 180.0}, 1780272000.0, 20);
  ASSERT_EQ(tiles.size(), 8u);  // 4 x 2 tiles of at most 20 texels a side
  weather::WeatherMap service = weather::forecast_map(f, 0.0, 64, 32);
  std::fill(service.rgba.begin(), service.rgba.end(), 0.9f);  // a map that had other weather
  service.layer_coverage.clear();
  for (const auto& t : tiles) {
    EXPECT_EQ(t.layer_channels, 0x0f);
    ASSERT_EQ(protocol::validate(protocol::Message(t)), std::nullopt);
    weather::apply_tile(service, to_map_tile(t));
  }
  const weather::WeatherMap expected = weather::forecast_map(f, 1780272000.0, 64, 32);
  ASSERT_TRUE(service.has_layer_coverage());
  for (std::size_t i = 0; i < expected.rgba.size(); ++i) {
    ASSERT_NEAR(service.rgba[i], expected.rgba[i], 1e-6f) << i;
    ASSERT_NEAR(service.layer_coverage[i], expected.layer_coverage[i], 1e-6f) << i;
  }
  float c[4];
  service.sample_layer_coverage(45.0, 10.0, c);
  EXPECT_GT(c[0] + c[1] + c[2] + c[3], 0.5f) << "cloud where the forecast has it";
}

TEST(MapTiles, LayerSlotsFollowTheChannelsInEachTexel) {
  MapRaster r = make_raster(3, 2, {protocol::tile_channel::kDensity, protocol::tile_channel::kCoverage});
  r.layer_channels = 0b0110;  // slots 1 and 2: two more values per texel
  r.values.clear();
  for (int texel = 0; texel < 6; ++texel) r.values.insert(r.values.end(), {0.1f, 0.2f, 0.3f, 0.4f});
  const auto tiles = split_into_tiles(r, GeoBounds{0, 0, 1, 1}, 0.0, 16);
  ASSERT_EQ(tiles.size(), 1u);
  EXPECT_EQ(tiles[0].layer_channels, 0b0110);
  EXPECT_EQ(tiles[0].channel_count(), 4);
  // coverage (raster value 1), density (value 0), then the slots as they are
  EXPECT_EQ(std::vector<float>(tiles[0].data.begin(), tiles[0].data.begin() + 4),
            (std::vector<float>{0.2f, 0.1f, 0.3f, 0.4f}));
  r.layer_channels = 0x10;
  EXPECT_THROW(split_into_tiles(r, GeoBounds{0, 0, 1, 1}, 0.0, 16), std::invalid_argument);
}

TEST(MapImage, ValuesOutsideTheUnitIntervalNameThePixel) {
  MapRaster r = make_raster(5, 4, {protocol::tile_channel::kCoverage, protocol::tile_channel::kPrecipitation});
  EXPECT_NO_THROW(check_map_values(r, "m.exr"));
  r.values[(2 * 5 + 3) * 2 + 1] = 1.5f;
  EXPECT_EQ(usage_error([&] { check_map_values(r, "m.exr"); }),
            "m.exr: pixel (x 3, y 2) channel 1 (precipitation): value 1.5 outside [0, 1]");
  r.values[(2 * 5 + 3) * 2 + 1] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(usage_error([&] { check_map_values(r, "m.exr"); }),
            "m.exr: pixel (x 3, y 2) channel 1 (precipitation): value nan is not finite");
}

TEST(MapImage, An8BitImageScalesToTheUnitIntervalAndTooFewChannelsIsAnError) {
  TempDir dir("mapimg");
  const fs::path png = dir.path() / "map.png";
  OIIO::ImageBuf buf(OIIO::ImageSpec(2, 1, 1, OIIO::TypeDesc::UINT8));
  const std::uint8_t px[2] = {0, 255};
  ASSERT_TRUE(buf.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, px));
  ASSERT_TRUE(buf.write(png.string()));
  const MapRaster r = read_map_image(png.string(), {protocol::tile_channel::kDensity});
  ASSERT_EQ(r.values.size(), 2u);
  EXPECT_EQ(r.values[0], 0.0f);
  EXPECT_EQ(r.values[1], 1.0f);
  EXPECT_EQ(usage_error([&] { read_map_image(png.string(), {1, 4}); }),
            png.string() + ": image has 1 channel(s) but --channels lists 2");
}

// ---- progress, summary, manifest ----------------------------------------------------------

TEST(Progress, BarShowsCountsPercentRateAndEta) {
  EXPECT_EQ(format_progress_bar(50, 100, 4.0, 10), "[#####-----]  50/100 frames   50%  12.5 frames/s  ETA 0:04");
  EXPECT_EQ(format_progress_bar(0, 7, 0.0, 7), "[-------]  0/7 frames    0%");
  EXPECT_EQ(format_progress_bar(9, 7, 1.0, 4, "poses"), "[####]  7/7 poses  100%  7.0 poses/s  ETA 0:00");
  EXPECT_EQ(format_progress_line("sweep", 3, 12, 1.25), "sweep: 25% (3/12 frames, 1.2 s)");
  EXPECT_EQ(format_duration(0.0), "0:00");
  EXPECT_EQ(format_duration(59.9), "0:59");
  EXPECT_EQ(format_duration(3725.0), "1:02:05");
  EXPECT_EQ(format_duration(-1.0), "--:--");
}

TEST(Progress, WithoutATerminalOneLinePerTenPercent) {
  std::ostringstream out;
  ProgressReporter p(out, false, 200, "replay");
  for (std::size_t i = 1; i <= 200; ++i) p.update(i, 0.01 * static_cast<double>(i));
  p.finish(200, 2.0);
  const std::string text = out.str();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 10);
  EXPECT_EQ(text.find('\r'), std::string::npos);
  EXPECT_NE(text.find("replay: 10% (20/200 frames, 0.2 s)\n"), std::string::npos);
  EXPECT_NE(text.find("replay: 100% (200/200 frames, 2.0 s)\n"), std::string::npos);
}

TEST(Progress, OnATerminalTheBarIsRedrawnInPlaceAndEndsItsLine) {
  std::ostringstream out;
  ProgressReporter p(out, true, 4, "replay");
  p.update(1, 0.5);
  p.update(2, 0.55);  // within 0.1 s of the last redraw: skipped
  p.update(3, 1.0);
  p.finish(4, 1.2);
  const std::string text = out.str();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\r'), 3);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1);
  EXPECT_EQ(text.back(), '\n');
  EXPECT_NE(text.find("4/4 frames  100%"), std::string::npos);
  EXPECT_EQ(text.find("2/4"), std::string::npos);
}

TEST(RunSummary, NearestRankP95AndTheSummaryLine) {
  std::vector<double> v;
  for (int i = 20; i >= 1; --i) v.push_back(i);
  const Distribution d = summarize(v);
  EXPECT_EQ(d.count, 20u);
  EXPECT_EQ(d.mean, 10.5);
  EXPECT_EQ(d.median, 10.0);  // the 10th of 20
  EXPECT_EQ(d.p95, 19.0);
  EXPECT_EQ(d.max, 20.0);
  EXPECT_EQ(summarize({3.0, 1.0, 2.0}).median, 2.0);
  EXPECT_EQ(summarize({}).count, 0u);

  ReplaySummary s;
  s.frames = 4;
  s.poses_sent = 10;
  s.wall_s = 2.0;
  s.latency_ms = {10, 20, 30, 40};
  s.render_ms = {5, 5, 5, 9};
  s.realtime = true;
  s.poses_refused = 1;
  EXPECT_EQ(format_replay_summary(s),
            "replay: 4 frames, 10 poses sent, 2.00 s, 2.00 frames/s, latency mean 25.0 ms p95 40.0 ms max 40.0 ms, "
            "render mean 6.0 ms; 5 poses superseded before rendering (latest wins); 1 poses refused by the service");
}

TEST(RunSummary, SweepLineHasRateAndLatencyMedianAndP95) {
  SweepSummary s;
  s.rows = 4;
  s.entries = 5;
  s.wall_s = 2.0;
  s.latency_ms = {40, 10, 30, 20};
  s.manifest = "/x/manifest.csv";
  s.refused = 1;
  EXPECT_EQ(format_sweep_summary(s),
            "sweep: 4 of 5 entries rendered in 2.00 s, 2.00 frames/s, latency median 20.0 ms p95 40.0 ms, manifest "
            "/x/manifest.csv; 1 refused by the service");
  s.refused = 0;
  s.nonfinite_frames = 2;
  s.rows = 0;
  s.latency_ms.clear();
  EXPECT_EQ(format_sweep_summary(s),
            "sweep: 0 of 5 entries rendered in 2.00 s, 0.00 frames/s, latency median 0.0 ms p95 0.0 ms, manifest "
            "/x/manifest.csv; 2 frames with NaN/Inf pixels");
}

TEST(Manifest, HeaderAndRowWithQuotedText) {
  EXPECT_EQ(manifest_header(),
            "frame,lat,lon,alt,heading,pitch,roll,utc,weather,render_ms,latency_ms,mean_radiance,cloud_fraction,"
            "nonfinite,file");
  ManifestRow r;
  r.frame = 42;
  r.lat_deg = 47.45;
  r.lon_deg = -8.5;
  r.alt_m = 2500;
  r.heading_deg = 270;
  r.pitch_deg = 5;
  r.roll_deg = -1.25;
  r.utc_unix_s = 1782043200.25;
  r.weather = "deck, thin";
  r.render_ms = 12.3456;
  r.latency_ms = 20;
  r.stats.mean_radiance = 0.0123456789;
  r.stats.cloud_fraction = 0.5;
  r.stats.nonfinite = 3;
  r.file = "/tmp/f/frame_000042.exr";
  EXPECT_EQ(manifest_line(r),
            "42,47.45,-8.5,2500,270,5,-1.25,2026-06-21T12:00:00.250Z,\"deck, thin\",12.346,20.000,0.0123457,0.500000,3,"
            "/tmp/f/frame_000042.exr");
}

// ---- weather-map flag values ----------------------------------------------------------------

TEST(FlagValues, MapBoundsAndChannelsWithOneLineNamingTheFlag) {
  const GeoBounds b = parse_flag_bounds("--bounds", "40,0,50,20");
  EXPECT_EQ(b.lat_min_deg, 40.0);
  EXPECT_EQ(b.lon_max_deg, 20.0);
  EXPECT_NO_THROW(parse_flag_bounds("--bounds", "-10,170,10,190"));
  EXPECT_NE(usage_error([] { parse_flag_bounds("--bounds", "40,0,50"); }), "");
  EXPECT_NE(usage_error([] { parse_flag_bounds("--bounds", "40,170,50,531"); }), "");
  EXPECT_EQ(parse_flag_channels("--channels", "density,coverage"),
            (std::vector<std::uint8_t>{protocol::tile_channel::kDensity, protocol::tile_channel::kCoverage}));
  EXPECT_EQ(usage_error([] { parse_flag_channels("--channels", "coverage,coverage"); }),
            "--channels coverage,coverage: channel coverage listed twice");
  EXPECT_EQ(usage_error([] { parse_flag_bounds("--bounds", "40, 0,50,20"); }),
            "--bounds 40, 0,50,20: expected lat_min,lon_min,lat_max,lon_max in degrees, e.g. 40,0,50,20");
}

// ---- replay poses, contact-sheet picks, watch counters -----------------------------------

TEST(ReplayPoses, ResampledPosesCarryUtcSimTimeAndATeleportOnTheFirst) {
  PoseTrack track;
  track.source = "log.csv";
  for (int i = 0; i < 3; ++i) {
    PoseSample s;
    s.unix_time_s = 1782043200.0 + 2.0 * i;
    s.position = {47.45, 8.56, 1500.0 + 100.0 * i};
    s.attitude = {90.0, 2.0, 0.0};
    track.samples.push_back(s);
  }
  const auto poses = replay_poses(track, 2.0, 0);
  ASSERT_EQ(poses.size(), 9u);  // 4 s at 2 Hz, both ends
  EXPECT_EQ(poses[0].flags, protocol::pose_flag::kTeleport);
  EXPECT_EQ(poses[1].flags, 0);
  EXPECT_EQ(poses[3].sim_time_s, 1.5);
  EXPECT_EQ(poses[3].utc_unix_s, std::optional<double>(1782043201.5));
  EXPECT_NEAR(poses[3].alt_m, 1575.0, 1e-9);
  EXPECT_EQ(replay_poses(track, 2.0, 4).size(), 4u);

  track.samples[1].position.alt_m = -1000.0;  // fine for a log, below the protocol's -500 m
  const std::string e = usage_error([&] { replay_poses(track, 1.0, 0); });
  EXPECT_EQ(e.rfind("log.csv: pose at 2026-06-21T12:00:02Z: Pose.alt_m", 0), 0u) << e;
}

TEST(ContactSheet, PicksAreEvenlySpacedWithBothEnds) {
  EXPECT_EQ(pick_evenly(5, 16), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(pick_evenly(0, 16), std::vector<std::size_t>{});
  EXPECT_EQ(pick_evenly(31, 4), (std::vector<std::size_t>{0, 10, 20, 30}));
  const auto p = pick_evenly(1000, 16);
  ASSERT_EQ(p.size(), 16u);
  EXPECT_EQ(p.front(), 0u);
  EXPECT_EQ(p.back(), 999u);
  for (std::size_t i = 1; i < p.size(); ++i) EXPECT_NEAR(static_cast<double>(p[i] - p[i - 1]), 66.6, 1.0);
}

TEST(ContactSheet, MosaicOfExrFramesHasTheGridLayoutAndToneMappedTiles) {
  TempDir dir("sheet");
  std::vector<SheetFrame> frames;
  for (int i = 0; i < 5; ++i) {
    const fs::path p = dir.path() / ("frame_" + std::to_string(i) + ".exr");
    OIIO::ImageBuf buf(OIIO::ImageSpec(40, 20, 4, OIIO::TypeDesc::HALF));
    const float radiance[4] = {0.05f * (i + 1), 0.05f * (i + 1), 0.05f * (i + 1), 1.0f};  // W m^-2 sr^-1 nm^-1
    OIIO::ImageBufAlgo::fill(buf, radiance);
    ASSERT_TRUE(buf.write(p.string()));
    frames.push_back({p.string(), 100u + static_cast<std::uint64_t>(i)});
  }
  const fs::path out = dir.path() / "sheet.png";
  write_contact_sheet(frames, out.string());
  OIIO::ImageBuf sheet(out.string());
  ASSERT_TRUE(sheet.read(0, 0, true, OIIO::TypeDesc::FLOAT));
  // 5 frames: 3 columns x 2 rows of 40x20 tiles, 4 px gaps around and between.
  EXPECT_EQ(sheet.spec().width, 3 * 40 + 4 * kContactSheetGap);
  EXPECT_EQ(sheet.spec().height, 2 * 20 + 3 * kContactSheetGap);
  float gap[3], tile[3], empty[3];
  sheet.getpixel(1, 1, gap, 3);
  sheet.getpixel(4 + 38, 4 + 18, tile, 3);                 // bottom-right corner of tile 0 (no label there)
  sheet.getpixel(4 + 2 * 44 + 20, 4 + 24 + 10, empty, 3);  // the sixth cell is empty
  EXPECT_NEAR(gap[0], 0.08f, 1.0f / 255.0f);
  EXPECT_NEAR(empty[0], 0.08f, 1.0f / 255.0f);
  // A uniform frame is auto-exposed to the key 0.18; ACES filmic gives 0.2669, the sRGB
  // transfer 0.5535 (141/255 after 8-bit rounding).
  EXPECT_NEAR(tile[0], 0.5535f, 1.0f / 255.0f);
  EXPECT_THROW(write_contact_sheet({}, out.string()), std::invalid_argument);
  EXPECT_THROW(write_contact_sheet({{(dir.path() / "absent.exr").string(), 1}}, out.string()), std::runtime_error);
}

TEST(WatchStats, CountsFramesGapsRateAndLatency) {
  WatchStats w(10);  // frames 1..10 were there before watching
  w.observe(10, 0.1);
  EXPECT_EQ(w.received(), 0u);
  w.observe(11, 0.2);
  w.record_latency(0.5);
  w.observe(12, 0.3);
  w.record_latency(1.5);
  w.observe(15, 0.4);  // 13 and 14 missed
  w.record_latency(0.25);
  EXPECT_EQ(w.received(), 3u);
  EXPECT_EQ(w.skipped(), 2u);
  cloudsvc_shm_slot info{};
  info.width = 64;
  info.height = 36;
  info.pixel_format = CLOUDSVC_SHM_RGBA8_SRGB;
  EXPECT_EQ(w.report_line(1.0, &info), "t 1.0 s: 3 frames (+3), 3.0 frames/s, newest #15 64x36 RGBA8 sRGB, skipped 2, "
                                       "latency mean 0.8 ms max 1.5 ms");
  w.start_interval(1.0);
  EXPECT_EQ(w.report_line(1.5, nullptr), "t 1.5 s: 3 frames (+0), 0.0 frames/s, newest #15, skipped 2, latency -");
  w.observe(1, 1.5);  // the service restarted
  w.record_latency(3.0);
  EXPECT_EQ(w.newest(), 1u);
  EXPECT_EQ(w.report_line(2.0, nullptr),
            "t 2.0 s: 4 frames (+1), 1.0 frames/s, newest #1, skipped 2, latency mean 3.0 ms max 3.0 ms");
  EXPECT_EQ(w.summary_line(2.0),
            "watch: 4 frames in 2.0 s (2.0 frames/s), newest #1, skipped 2, latency mean 1.3 ms max 3.0 ms");
  EXPECT_EQ(WatchStats(0).report_line(1.0, nullptr), "t 1.0 s: 0 frames (+0), 0.0 frames/s, newest #0, skipped 0, latency -");
  EXPECT_EQ(WatchStats(0).summary_line(1.0), "watch: 0 frames in 1.0 s (0.0 frames/s), newest #0, skipped 0");
}

}  // namespace
}  // namespace cloudsvc::sim
