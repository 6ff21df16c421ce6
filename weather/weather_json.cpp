// Weather JSON files: strict parsing with one-line errors, and serialisation.
// Format and rules: docs/WEATHER.md ("Weather files").
#include "weather/weather_json.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <string_view>
#include <vector>

namespace cloudsvc::weather {
namespace {

using nlohmann::json;

constexpr std::size_t kMaxFileBytes = 16u << 20;  // weather files are a few hundred bytes

// Messages are one line whatever the input contains.
std::string one_line(std::string s) {
  for (char& c : s) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return s;
}

[[noreturn]] void fail(const std::string& source, const std::string& field,
                       const std::string& problem) {
  throw WeatherFileError(one_line(source + ": " + field + ": " + problem));
}

// Appends j as compact JSON (as j.dump() writes it) to out, stopping once out is longer
// than `limit`. Every nesting level writes a bracket before going deeper, so recursion and
// work stay within `limit` however deep or long j is (j.dump() recurses once per level: a
// file of nested '[' overflowed the stack).
void dump_prefix(const json& j, std::string& out, std::size_t limit) {
  if (!j.is_structured()) {
    out += j.dump();
    return;
  }
  out += j.is_array() ? '[' : '{';
  for (auto it = j.begin(); it != j.end() && out.size() <= limit; ++it) {
    if (it != j.begin()) out += ',';
    if (j.is_object()) out += json(it.key()).dump() + ':';
    dump_prefix(it.value(), out, limit);
  }
  out += j.is_array() ? ']' : '}';
}

// "string \"lots\"", "number 3", ... shortened for messages.
std::string describe(const json& j) {
  std::string text;
  dump_prefix(j, text, 40);
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return std::string(j.type_name()) + " " + text;
}

double get_number(const json& j, const std::string& source, const std::string& field) {
  if (!j.is_number()) fail(source, field, "expected a number, got " + describe(j));
  const double v = j.get<double>();
  // The parser rejects overflowing literals; an integer beyond double range cannot occur.
  if (!std::isfinite(v)) fail(source, field, "not a finite number");
  return v;
}

std::string get_string(const json& j, const std::string& source, const std::string& field) {
  if (!j.is_string()) fail(source, field, "expected a string, got " + describe(j));
  return j.get<std::string>();
}

// Rejects keys outside `allowed` (typo protection): "coverge" must not silently become the
// default coverage.
void check_keys(const json& obj, std::initializer_list<std::string_view> allowed,
                const std::string& source, const std::string& path) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    if (std::find(allowed.begin(), allowed.end(), it.key()) != allowed.end()) continue;
    std::string list;
    for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    fail(source, path.empty() ? it.key() : path + "." + it.key(),
         "unknown key (expected one of: " + list + ")");
  }
}

std::string type_list() {
  std::string list;
  for (CloudType t : all_cloud_types()) {
    list += (list.empty() ? "" : ", ") + std::string(cloud_type_name(t));
  }
  return list;
}

CloudLayer parse_layer(const json& j, const std::string& source, const std::string& path) {
  if (!j.is_object()) fail(source, path, "expected an object, got " + describe(j));
  check_keys(j,
             {"type", "base_m", "top_m", "coverage", "density_scale", "droplet_diameter_um",
              "wind_mps"},
             source, path);
  if (!j.contains("type")) fail(source, path + ".type", "missing (required)");
  const std::string type_name = get_string(j["type"], source, path + ".type");
  const auto type = cloud_type_from_name(type_name);
  if (!type || *type == CloudType::None) {
    fail(source, path + ".type",
         "unknown cloud type \"" + type_name + "\" (expected one of: " + type_list() +
             ", or their two-letter abbreviations)");
  }
  CloudLayer layer = default_layer(*type);
  const auto field = [&](const char* key) { return path + "." + key; };

  if (!j.contains("coverage")) fail(source, field("coverage"), "missing (required)");
  layer.coverage = get_number(j["coverage"], source, field("coverage"));

  // Altitudes: a missing one keeps the type's default thickness next to the given one.
  const double thickness = layer.top_m - layer.base_m;
  const bool has_base = j.contains("base_m"), has_top = j.contains("top_m");
  if (has_base) layer.base_m = get_number(j["base_m"], source, field("base_m"));
  if (has_top) layer.top_m = get_number(j["top_m"], source, field("top_m"));
  if (has_base && !has_top) layer.top_m = layer.base_m + thickness;
  if (has_top && !has_base) layer.base_m = layer.top_m - thickness;

  if (j.contains("density_scale")) {
    layer.density_scale = get_number(j["density_scale"], source, field("density_scale"));
  }
  if (j.contains("droplet_diameter_um")) {
    layer.droplet_diameter_um =
        get_number(j["droplet_diameter_um"], source, field("droplet_diameter_um"));
  }
  if (j.contains("wind_mps")) {
    const json& w = j["wind_mps"];
    if (!w.is_array() || w.size() != 2) {
      fail(source, field("wind_mps"), "expected [east, north] in m/s, got " + describe(w));
    }
    layer.wind.east_mps = get_number(w[0], source, field("wind_mps") + "[0]");
    layer.wind.north_mps = get_number(w[1], source, field("wind_mps") + "[1]");
  }
  return layer;
}

// Line and column (1-based) of byte offset `pos` in text.
std::string position_of(const std::string& text, std::size_t pos) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < pos && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// nlohmann's exception text without its "[json.exception.<kind>.<id>] " prefix.
std::string strip_exception_id(const std::string& what) {
  if (!what.empty() && what[0] == '[') {
    const std::size_t close = what.find("] ");
    if (close != std::string::npos) return what.substr(close + 2);
  }
  return what;
}

json parse_text(const std::string& text, const std::string& source) {
  // Duplicate keys: nlohmann keeps the last one silently; a parse callback sees every key
  // and can refuse a repeat within the same object. The callback also tracks the path
  // (object keys, array indices) so the message can name the field.
  struct Frame {
    bool array = false;
    long index = -1;             // arrays: index of the current element
    std::string key;             // objects: the current key
    std::set<std::string> keys;  // objects: keys seen so far
  };
  std::vector<Frame> frames;
  const auto path_to = [&frames](const std::string& key) {
    std::string path;
    for (std::size_t i = 0; i + 1 < frames.size(); ++i) {
      if (frames[i].array) {
        path += '[';
        path += std::to_string(frames[i].index);
        path += ']';
      } else {
        path += (path.empty() ? "" : ".") + frames[i].key;
      }
    }
    return path + (path.empty() ? "" : ".") + key;
  };
  const json::parser_callback_t reject_duplicates = [&](int, json::parse_event_t event,
                                                        json& parsed) {
    using E = json::parse_event_t;
    const bool element_starts = event == E::object_start || event == E::array_start ||
                                event == E::value;
    if (element_starts && !frames.empty() && frames.back().array) ++frames.back().index;
    if (event == E::object_start || event == E::array_start) {
      frames.emplace_back();
      frames.back().array = event == E::array_start;
    } else if (event == E::object_end || event == E::array_end) {
      if (!frames.empty()) frames.pop_back();
    } else if (event == E::key && !frames.empty()) {
      Frame& f = frames.back();
      f.key = parsed.get<std::string>();
      if (!f.keys.insert(f.key).second) {
        fail(source, path_to(f.key), "duplicate key (each key may appear once per object)");
      }
    }
    return true;
  };
  try {
    return json::parse(text, reject_duplicates, /*allow_exceptions=*/true,
                       /*ignore_comments=*/false);
  } catch (const json::parse_error& e) {
    // "parse error at line L, column C: <what>" -> add the byte offset after the position.
    std::string msg = strip_exception_id(e.what());
    const std::size_t colon = msg.find(": ");
    if (colon != std::string::npos) {
      msg.insert(colon, " (byte " + std::to_string(e.byte) + ")");
    }
    throw WeatherFileError(one_line(source + ": " + msg));
  } catch (const json::out_of_range& e) {
    // Number overflow (e.g. 1e999): JSON has no Inf or NaN. nlohmann gives no position, so
    // point at the first occurrence of the offending literal.
    std::string msg = strip_exception_id(e.what());
    const std::size_t q0 = msg.find('\''), q1 = msg.rfind('\'');
    std::string where = "number";
    if (q0 != std::string::npos && q1 > q0) {
      const std::size_t at = text.find(msg.substr(q0 + 1, q1 - q0 - 1));
      if (at != std::string::npos) where = position_of(text, at);
    }
    throw WeatherFileError(
        one_line(source + ": " + where + ": " + msg + " (numbers must be finite)"));
  } catch (const json::exception& e) {
    throw WeatherFileError(one_line(source + ": " + strip_exception_id(e.what())));
  }
}

}  // namespace

Weather parse_weather_json(const std::string& text, const std::string& source_name) {
  const json root = parse_text(text, source_name);
  if (!root.is_object()) {
    fail(source_name, "(top level)", "expected an object, got " + describe(root));
  }
  check_keys(root, {"name", "map_seed", "ground_albedo", "visibility_m", "layers"}, source_name, "");

  Weather w;
  w.name = root.contains("name") ? get_string(root["name"], source_name, "name") : source_name;
  if (root.contains("map_seed")) {
    const json& s = root["map_seed"];
    if (!s.is_number_unsigned() || s.get<std::uint64_t>() > std::numeric_limits<std::uint32_t>::max()) {
      fail(source_name, "map_seed",
           "expected an integer in [0, 4294967295], got " + describe(s));
    }
    w.map_seed = static_cast<std::uint32_t>(s.get<std::uint64_t>());
  }
  if (root.contains("ground_albedo")) {
    Weather probe;  // the range rule of validate_detail
    probe.ground_albedo = get_number(root["ground_albedo"], source_name, "ground_albedo");
    if (auto issue = validate_detail(probe)) fail(source_name, issue->field, issue->problem);
    w.ground_albedo = probe.ground_albedo;
  }
  if (root.contains("visibility_m")) {
    Weather probe;  // the range rule of validate_detail
    probe.visibility_m = get_number(root["visibility_m"], source_name, "visibility_m");  // m
    if (auto issue = validate_detail(probe)) fail(source_name, issue->field, issue->problem);
    w.visibility_m = probe.visibility_m;
  }

  std::vector<std::pair<CloudLayer, int>> layers;  // with their index in the file
  if (root.contains("layers")) {
    const json& arr = root["layers"];
    if (!arr.is_array()) fail(source_name, "layers", "expected an array, got " + describe(arr));
    if (arr.size() > static_cast<std::size_t>(kMaxCloudLayers)) {
      fail(source_name, "layers",
           std::to_string(arr.size()) + " layers, at most " + std::to_string(kMaxCloudLayers) +
               " allowed");
    }
    for (std::size_t i = 0; i < arr.size(); ++i) {
      const int index = static_cast<int>(i);
      const CloudLayer layer =
          parse_layer(arr[i], source_name, "layers[" + std::to_string(i) + "]");
      if (auto issue = validate_layer(layer, index)) fail(source_name, issue->field, issue->problem);
      layers.emplace_back(layer, index);
    }
  }

  // Sort by base; report overlaps with the indices the author wrote.
  std::stable_sort(layers.begin(), layers.end(), [](const auto& a, const auto& b) {
    return a.first.base_m < b.first.base_m;
  });
  const auto span = [](const CloudLayer& l) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g to %.10g m", l.base_m, l.top_m);
    return std::string(buf);
  };
  for (std::size_t k = 1; k < layers.size(); ++k) {
    const auto& [lower, lower_index] = layers[k - 1];
    const auto& [upper, upper_index] = layers[k];
    if (upper.base_m < lower.top_m) {
      fail(source_name, "layers[" + std::to_string(upper_index) + "]",
           std::string("(") + span(upper) + ") overlaps layers[" + std::to_string(lower_index) + "] (" +
               span(lower) + ")");
    }
  }
  for (const auto& entry : layers) w.layers.push_back(entry.first);

  if (auto issue = validate_detail(w)) fail(source_name, issue->field, issue->problem);
  return w;
}

Weather load_weather_json(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw WeatherFileError(one_line(path + ": cannot open: " + std::strerror(errno)));
  std::string text;
  char buf[4096];
  std::size_t got = 0;
  while ((got = std::fread(buf, 1, sizeof buf, f)) > 0) {
    text.append(buf, got);
    if (text.size() > kMaxFileBytes) {
      std::fclose(f);
      throw WeatherFileError(one_line(path + ": cannot read: larger than " +
                                      std::to_string(kMaxFileBytes >> 20) + " MiB"));
    }
  }
  const bool failed = std::ferror(f) != 0;
  const int err = errno;
  std::fclose(f);
  if (failed) throw WeatherFileError(one_line(path + ": cannot read: " + std::strerror(err)));
  return parse_weather_json(text, path);
}

std::string to_json(const Weather& w) {
  nlohmann::ordered_json root;
  root["name"] = w.name;
  root["map_seed"] = w.map_seed;
  if (w.ground_albedo) root["ground_albedo"] = *w.ground_albedo;
  if (w.visibility_m) root["visibility_m"] = *w.visibility_m;
  root["layers"] = nlohmann::ordered_json::array();
  for (const CloudLayer& l : w.layers) {
    nlohmann::ordered_json j;
    j["type"] = std::string(cloud_type_name(l.type));
    j["base_m"] = l.base_m;
    j["top_m"] = l.top_m;
    j["coverage"] = l.coverage;
    j["density_scale"] = l.density_scale;
    j["droplet_diameter_um"] = l.droplet_diameter_um;
    j["wind_mps"] = {l.wind.east_mps, l.wind.north_mps};
    root["layers"].push_back(std::move(j));
  }
  return root.dump(2) + "\n";
}

}  // namespace cloudsvc::weather
