// `sim_client weather`: sends cloud layers (a weather file or preset) and/or a weather map
// image split into protocol tiles, or a forecast (GRIB2, METAR) as the layers of a region
// and each step's layer coverage as tiles, then reports whether the service accepted them.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <memory>
#include <thread>
#include <tuple>

#include "common/option_address.h"
#include "common/option_values.h"
#include "common/option_weather.h"
#include "geodesy/utc_time.h"
#include "protocol/validate.h"
#include "protocol/weather_conversion.h"
#include "sim_client/client_session.h"
#include "sim_client/commands.h"
#include "sim_client/map_flags.h"
#include "sim_client/map_image.h"
#include "sim_client/forecast_raster.h"
#include "sim_client/map_tiles.h"
#include "sim_client/text_input.h"
#include "sim_client/usage_errors.h"
#include "weather/forecast_frame.h"
#include "weather/grib_reader.h"
#include "weather/presets.h"
#include "weather/weather_timeline.h"

namespace cloudsvc::sim {

namespace {

constexpr const char* kName = "weather";

struct WeatherArgs {
  std::string connect = kDefaultAddress, layers, preset, map, bounds, valid_at, channels = "coverage", quiet_ms = "500";
  std::vector<std::string> grib, metar;  // forecast files
  std::string at, map_size;  // map_size empty: the service's map, 1024x512
};

// A forecast to send: its layers around a point and its steps' maps (forecast_raster.h).
struct ForecastToSend {
  std::shared_ptr<const weather::ForecastWeather> weather;
  std::string flag;                    // --grib or --metar, for messages
  double lat_deg = 0.0, lon_deg = 0.0;  // where the layers are made
  double utc_s = 0.0;                   // when: the layers' time and the steps around it
  int map_width = 1024, map_height = 512;
};

struct WeatherOptions {
  std::string address;
  std::optional<weather::Weather> layers;  // from --layers or --preset
  std::string layers_label;
  std::string map;                         // image path; empty = none
  GeoBounds bounds;
  double valid_at_utc_s = 0.0;
  std::vector<std::uint8_t> channels;
  std::chrono::milliseconds quiet{500};
  std::optional<ForecastToSend> forecast;  // --grib or --metar
};

ForecastToSend validate_forecast(const WeatherArgs& a) {
  if (!a.grib.empty() && !a.metar.empty()) cli::fail("--metar", cli::join(a.metar, " "), "give either --grib or --metar, not both");
  for (const auto& [flag, value] : {std::pair{"--layers", &a.layers}, std::pair{"--preset", &a.preset}, std::pair{"--map", &a.map}})
    if (!value->empty()) cli::fail(flag, *value, "not with a forecast (--grib, --metar): it sends its own layers and map");
  if (a.at.empty()) cli::fail("--at", a.at, "required with --grib or --metar: LAT,LON[,TIME], where the layers are made");
  ForecastToSend f;
  f.flag = a.grib.empty() ? "--metar" : "--grib";
  const std::vector<std::string>& files = a.grib.empty() ? a.metar : a.grib;
  for (const std::string& path : files)
    if (weather::is_grib_path(path) != (f.flag == "--grib"))
      cli::fail(f.flag, path, f.flag == "--grib" ? "expected a GRIB2 file (.grib2, .grb2, .grib, .grb)"
                                                 : "expected METAR reports (.metar, .txt)");
  const cli::PlaceAndTime at = cli::parse_place_and_time("--at", a.at);
  f.lat_deg = at.lat_deg;
  f.lon_deg = at.lon_deg;
  // METAR reports carry only a day of the month: the time of --at dates them, else now.
  const double now_s = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  f.weather = cli::load_forecast(f.flag, files, at.utc_s.value_or(now_s));
  f.utc_s = at.utc_s.value_or(f.weather->valid_times().front());
  if (!a.map_size.empty()) std::tie(f.map_width, f.map_height) = cli::parse_image_size("--map-size", a.map_size, 4096);
  return f;
}

WeatherOptions validate(const WeatherArgs& a) {
  WeatherOptions o;
  cli::parse_endpoint("--connect", a.connect, cli::PortUse::Connect);
  o.address = a.connect;
  o.quiet = std::chrono::milliseconds(cli::parse_integer("--quiet-ms", a.quiet_ms, 0, 60000, "milliseconds"));
  if (!a.grib.empty() || !a.metar.empty()) {
    o.forecast = validate_forecast(a);
    return o;
  }
  for (const auto& [flag, value] : {std::pair{"--at", &a.at}, std::pair{"--map-size", &a.map_size}})
    if (!value->empty()) cli::fail(flag, *value, "only with --grib or --metar");
  if (!a.layers.empty() && !a.preset.empty()) cli::fail("--preset", a.preset, "give either --layers or --preset, not both");
  if (a.layers.empty() && a.preset.empty() && a.map.empty())
    throw UsageError("nothing to send: give --layers FILE.json, --preset NAME, --map IMAGE, --grib FILE or --metar FILE");
  if (!a.preset.empty()) {
    o.layers = cli::weather_preset("--preset", a.preset);
    o.layers_label = "preset " + a.preset;
  }
  if (!a.layers.empty()) {
    o.layers = cli::load_weather_file("--layers", a.layers);
    o.layers_label = "layers from " + a.layers;
  }
  if (a.map.empty()) {
    for (const auto& [flag, value] : {std::pair{"--bounds", &a.bounds}, std::pair{"--valid-at", &a.valid_at}})
      if (!value->empty()) cli::fail(flag, *value, "only with --map");
  } else {
    if (a.bounds.empty()) cli::fail("--bounds", a.bounds, "required with --map: lat_min,lon_min,lat_max,lon_max in degrees");
    if (a.valid_at.empty()) cli::fail("--valid-at", a.valid_at, "required with --map: the UTC time the map is valid at");
    o.map = a.map;
    o.bounds = parse_flag_bounds("--bounds", a.bounds);
    o.valid_at_utc_s = cli::parse_time("--valid-at", a.valid_at);
    o.channels = parse_flag_channels("--channels", a.channels);
  }
  return o;
}

// What was sent, for matching Errors to it.
struct Sent {
  std::uint64_t seq = 0;
  std::string what;
};

// Sends the forecast's layers around its point, then the map of each step around its time
// (at most the service's keyframes: weather/weather_timeline.h) as tiles valid at the step's
// time. Returns the summary line.
std::string send_forecast(ClientSession& session, const ForecastToSend& f, std::vector<Sent>& sent) {
  if (session.welcome().minor < 2)
    throw RunError("the service speaks protocol " + std::to_string(session.welcome().major) + "." +
                   std::to_string(session.welcome().minor) + "; forecast weather (layer-coverage tiles) needs 1.2");
  if (!session.offers(protocol::capability::kWeatherTiles))
    throw RunError("the service does not accept weather map tiles (no WeatherTiles capability)");
  const weather::Weather layers = weather::forecast_weather_at(*f.weather, f.lat_deg, f.lon_deg, f.utc_s);
  sent.push_back({session.send(to_message(layers)), "the forecast's layers"});
  const std::vector<double> steps = f.weather->valid_times();
  const auto [first, count] = weather::keyframe_steps_around(steps, f.utc_s, weather::WeatherTimeline::kMaxKeyframes);
  const std::uint32_t side = tile_side_for(session.welcome().limits, 8);
  std::size_t tile_count = 0;
  for (std::size_t s = first; s < first + count; ++s) {
    const std::string step = "step " + geo::format_utc_iso8601(steps[s]);
    const MapRaster raster = forecast_raster(*f.weather, steps[s], f.map_width, f.map_height);
    const std::vector<protocol::WeatherMapTile> tiles = split_into_tiles(raster, GeoBounds{-90.0, -180.0, 90.0, 180.0}, steps[s], side);
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      if (auto problem = protocol::validate(protocol::Message(tiles[i])))
        throw RunError(step + ", tile " + std::to_string(i + 1) + ": " + *problem);
      sent.push_back({session.send(tiles[i]), step + ", tile " + std::to_string(i + 1) + "/" + std::to_string(tiles.size())});
    }
    tile_count += tiles.size();
  }
  return "weather: sent the forecast " + f.weather->name() + ": " + std::to_string(layers.layers.size()) +
         " layer" + (layers.layers.size() == 1 ? "" : "s") + " around " + format_number(f.lat_deg) + "," +
         format_number(f.lon_deg) + " at " + geo::format_utc_iso8601(f.utc_s) + ", " + std::to_string(count) +
         " step" + (count == 1 ? "" : "s") + " from " + geo::format_utc_iso8601(steps[first]) + " as " +
         std::to_string(tile_count) + (tile_count == 1 ? " tile (" : " tiles (") + std::to_string(f.map_width) + "x" +
         std::to_string(f.map_height) + " texels each step)";
}

int run_weather(const WeatherOptions& o) {
  // Read and check everything before connecting.
  std::vector<protocol::WeatherMapTile> tiles;
  MapRaster raster;
  if (!o.map.empty()) raster = read_map_image(o.map, o.channels);

  ClientSession session(o.address, "sim_client weather");
  std::vector<Sent> sent;
  std::string forecast_summary;
  if (o.forecast) forecast_summary = send_forecast(session, *o.forecast, sent);
  if (o.layers) {
    const protocol::WeatherLayers m = to_message(*o.layers);
    if (m.layers.size() > session.welcome().limits.max_layers)
      throw RunError(o.layers_label + ": " + std::to_string(m.layers.size()) + " layers, the service takes at most " +
                     std::to_string(session.welcome().limits.max_layers));
    sent.push_back({session.send(m), o.layers_label});
  }
  if (!o.map.empty()) {
    if (!session.offers(protocol::capability::kWeatherTiles))
      throw RunError("the service does not accept weather map tiles (no WeatherTiles capability)");
    const std::uint32_t side = tile_side_for(session.welcome().limits, static_cast<int>(o.channels.size()));
    tiles = split_into_tiles(raster, o.bounds, o.valid_at_utc_s, side);
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      if (auto problem = protocol::validate(protocol::Message(tiles[i])))
        throw RunError("tile " + std::to_string(i + 1) + " of " + o.map + ": " + *problem);
      sent.push_back({session.send(tiles[i]), "tile " + std::to_string(i + 1) + "/" + std::to_string(tiles.size()) +
                                                  " (" + std::to_string(tiles[i].width) + "x" +
                                                  std::to_string(tiles[i].height) + " texels)"});
    }
  }
  // Errors from decoding and validation come before the Stats answer; errors from applying
  // a tile on the render thread may come a little later: listen for a quiet period too.
  std::vector<protocol::Error> errors = session.sync(std::chrono::milliseconds(30000));
  const auto quiet_end = Clock::now() + o.quiet;
  while (Clock::now() < quiet_end)
    if (auto m = session.next(quiet_end))
      if (auto* e = std::get_if<protocol::Error>(&*m)) errors.push_back(*e);

  for (const protocol::Error& e : errors) {
    std::string about = "a message";
    for (const Sent& s : sent)
      if (s.seq == e.answers_seq) about = s.what;
    warn(kName, "service error about " + about + ": " + describe_error(e));
  }
  if (o.forecast) std::printf("%s\n", forecast_summary.c_str());
  if (o.layers) std::printf("weather: sent %s (%zu layer%s)\n", o.layers_label.c_str(), o.layers->layers.size(),
                            o.layers->layers.size() == 1 ? "" : "s");
  if (!o.map.empty()) {
    std::string names;
    for (std::uint8_t c : o.channels) names += (names.empty() ? "" : ",") + channel_name(c);
    std::printf("weather: sent %s as %zu tiles (%dx%d texels, channels %s, bounds %s,%s,%s,%s, valid at %s)\n",
                o.map.c_str(), tiles.size(), raster.width, raster.height, names.c_str(),
                format_number(o.bounds.lat_min_deg).c_str(), format_number(o.bounds.lon_min_deg).c_str(),
                format_number(o.bounds.lat_max_deg).c_str(), format_number(o.bounds.lon_max_deg).c_str(),
                geo::format_utc_iso8601(o.valid_at_utc_s).c_str());
  }
  std::printf(errors.empty() ? "weather: accepted (no error from the service)\n"
                             : "weather: %zu error(s) from the service\n",
              errors.size());
  std::fflush(stdout);
  return errors.empty() ? cli::kExitOk : cli::kExitFailure;
}

}  // namespace

Command add_weather_command(CLI::App& app) {
  auto args = std::make_shared<WeatherArgs>();
  CLI::App* cmd = app.add_subcommand(
      kName, "Send cloud layers (--layers or --preset) and/or a weather map image (--map) to the service and report "
             "whether it accepted them");
  cmd->add_option("--connect", args->connect, connect_help())->type_name("ADDR");
  cmd->add_option("--layers", args->layers, "Weather file (docs/WEATHER.md) whose layers replace the service's layer stack")
      ->type_name("FILE.json");
  cmd->add_option("--preset", args->preset,
                  "Weather preset whose layers replace the service's: " + cli::join(weather::preset_names(), ", "))
      ->type_name("NAME");
  cmd->add_option("--map", args->map,
                  "Weather map image (EXR, TIFF, PNG, ... read by OpenImageIO): top row = north edge, values in [0, 1] "
                  "(integer images scale to [0, 1]); its first N channels are the N --channels; sent as tiles of at "
                  "most 1024x1024 texels")
      ->type_name("IMAGE");
  cmd->add_option("--bounds", args->bounds,
                  "With --map: area the image covers, lat_min,lon_min,lat_max,lon_max in degrees (WGS84); "
                  "lon_max > 180 crosses the antimeridian")
      ->type_name("S,W,N,E");
  cmd->add_option("--valid-at", args->valid_at,
                  "With --map: UTC time the map is valid at, ISO 8601 (e.g. 2026-06-21T12:00Z); the service blends "
                  "between map states in time")
      ->type_name("UTC");
  cmd->add_option("--channels", args->channels,
                  "With --map: comma-separated map channels of the image's channels in order: coverage, development "
                  "(vertical development), density, precipitation, albedo (0.5 = the layer's own value; precipitation "
                  "0 = none; albedo: the ground's grey albedo 0..1, applied from the next frame); default coverage")
      ->type_name("LIST");
  cmd->add_option("--grib", args->grib,
                  "GRIB2 forecast files (.grib2, .grb2, .grib, .grb; docs/WEATHER.md) to send: the layers of the region "
                  "around --at and, for each forecast step around its time (at most 8), the global map of the layers' "
                  "coverage as tiles valid at the step's time")
      ->type_name("FILE...");
  cmd->add_option("--metar", args->metar,
                  "METAR or SPECI reports (.metar, .txt; one report per line) to send like --grib; they are dated by "
                  "the time of --at, else by the current date")
      ->type_name("FILE...");
  cmd->add_option("--at", args->at,
                  "With --grib or --metar: where and when the layers are made, LAT,LON in degrees and optionally ,TIME "
                  "in UTC ISO 8601; without TIME the first forecast step")
      ->type_name("LAT,LON[,TIME]");
  cmd->add_option("--map-size", args->map_size,
                  "With --grib or --metar: global map size of each step, WxH texels (each side at most 4096); "
                  "default 1024x512, the service's map")
      ->type_name("WxH");
  cmd->add_option("--quiet-ms", args->quiet_ms,
                  "After the service has taken every message, listen this long for late errors, milliseconds, "
                  "[0, 60000]; default 500")
      ->type_name("MS");
  cmd->footer(std::string(kExitCodesHelp) +
              "\nExamples: sim_client weather --preset overcast-stratus --connect unix:/tmp/cloudsvc.sock\n"
              "          sim_client weather --map coverage.exr --bounds 40,0,50,20 --valid-at 2026-06-21T12:00Z "
              "--channels coverage,density --connect unix:/tmp/cloudsvc.sock\n"
              "          sim_client weather --grib gfs.grib2 --at 47.45,8.56,2026-06-21T12:00Z --connect "
              "unix:/tmp/cloudsvc.sock");
  return {cmd, [args]() -> int { return run_weather(validate(*args)); }};
}

}  // namespace cloudsvc::sim
