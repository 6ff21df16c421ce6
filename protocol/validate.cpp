#include "protocol/validate.h"

#include <charconv>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <string_view>

#include "protocol/limits.h"
#include "protocol/utf8.h"
#include "protocol/weather_conversion.h"
#include "weather/map_tile.h"

namespace cloudsvc::protocol {
namespace {

using Problem = std::optional<std::string>;

// Shortest text that reads back to v ("91", "1e+300", "nan", "-inf").
std::string num(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

template <std::integral T>
std::string num(T v) {
  return std::to_string(v);
}

// Concatenation by appending (GCC 12 warns falsely about "literal" + std::string chains).
template <class... Parts>
std::string join(const Parts&... parts) {
  std::string s;
  (s.append(std::string_view(parts)), ...);
  return s;
}

Problem not_finite(std::string_view field, double v) {
  return join(field, " is ", num(v), " (must be finite)");
}

// v in [lo, hi].
Problem closed(std::string_view field, double v, double lo, double hi) {
  if (!std::isfinite(v)) return not_finite(field, v);
  if (v < lo || v > hi) {
    return join(field, " ", num(v), " out of range [", num(lo), ", ", num(hi), "]");
  }
  return {};
}

// v in (lo, hi].
Problem open_closed(std::string_view field, double v, double lo, double hi) {
  if (!std::isfinite(v)) return not_finite(field, v);
  if (v <= lo || v > hi) {
    return join(field, " ", num(v), " out of range (", num(lo), ", ", num(hi), "]");
  }
  return {};
}

// v in [lo, hi).
Problem closed_open(std::string_view field, double v, double lo, double hi) {
  if (!std::isfinite(v)) return not_finite(field, v);
  if (v < lo || v >= hi) {
    return join(field, " ", num(v), " out of range [", num(lo), ", ", num(hi), ")");
  }
  return {};
}

Problem finite(std::string_view field, double v) {
  if (!std::isfinite(v)) return not_finite(field, v);
  return {};
}

Problem nonnegative(std::string_view field, double v) {
  if (!std::isfinite(v)) return not_finite(field, v);
  if (v < 0.0) return join(field, " ", num(v), " is negative");
  return {};
}

Problem count_in(std::string_view field, std::uint64_t v, std::uint64_t lo, std::uint64_t hi) {
  if (v < lo || v > hi) {
    return join(field, " ", num(v), " out of range [", num(lo), ", ", num(hi), "]");
  }
  return {};
}

Problem known_bits(std::string_view field, std::uint32_t v, std::uint32_t all) {
  if (v & ~all) {
    char hex[16];
    const auto r = std::to_chars(hex, hex + sizeof hex, v & ~all, 16);
    return join(field, " has unknown bits 0x", std::string_view(hex, r.ptr - hex));
  }
  return {};
}

enum class TextKind {
  OneLine,  // any UTF-8 without control characters
  Name,     // ASCII letters, digits, '_', '-', '.'
};

Problem text(std::string_view field, std::string_view s, std::size_t max_bytes, TextKind kind) {
  if (s.size() > max_bytes) {
    return join(field, " is ", num(s.size()), " bytes long (at most ", num(max_bytes), ")");
  }
  if (!is_valid_utf8(s)) return join(field, " is not valid UTF-8");
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f) return join(field, " contains a control character");
    if (kind == TextKind::Name) {
      const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '_' || c == '-' || c == '.';
      if (!ok) return join(field, " may contain only letters, digits, '_', '-' and '.'");
    }
  }
  return {};
}

#define CHECK(expr)                  \
  do {                               \
    if (auto p_ = (expr)) return p_; \
  } while (false)

Problem check(const Hello& m) {
  // Version numbers are judged by the handshake; unknown capability bits are a newer
  // client's wishes and are ignored.
  CHECK(text("Hello.client_name", m.client_name, kMaxNameBytes, TextKind::OneLine));
  return {};
}

Problem check(const Welcome& m) {
  CHECK(text("Welcome.service_version", m.service_version, kMaxVersionBytes, TextKind::OneLine));
  const Limits& l = m.limits;
  CHECK(count_in("Welcome.limits.max_payload_bytes", l.max_payload_bytes, 1024, kMaxPayloadBytes));
  CHECK(count_in("Welcome.limits.max_image_size", l.max_image_size, 1, kMaxImageSize));
  CHECK(count_in("Welcome.limits.max_layers", l.max_layers, 0, kMaxLayers));
  CHECK(count_in("Welcome.limits.max_tile_size", l.max_tile_size, 1, kMaxTileSize));
  return {};
}

Problem check(const SetView& m) {
  CHECK(count_in("SetView.width", m.width, 1, kMaxImageSize));
  CHECK(count_in("SetView.height", m.height, 1, kMaxImageSize));
  CHECK(open_closed("SetView.hfov_deg", m.hfov_deg, 0.0, kMaxHfov_deg));
  CHECK(known_bits("SetView.sinks", m.sinks, sink::kAll));
  if (m.sinks == 0) return "SetView.sinks is empty (at least one of shm, window, file)";
  if (m.shm_format != ShmPixelFormat::Rgba16fLinear && m.shm_format != ShmPixelFormat::Rgba8Srgb) {
    return join("SetView.shm_format ", num(static_cast<std::uint64_t>(m.shm_format)),
                " unknown (0 RGBA16F linear, 1 RGBA8 sRGB)");
  }
  CHECK(text("SetView.file_dir", m.file_dir, kMaxPathBytes, TextKind::OneLine));
  if ((m.sinks & sink::kFile) && m.file_dir.empty()) {
    return "SetView.file_dir is empty but the file sink is requested";
  }
  if (m.file_format != FileFormat::Png && m.file_format != FileFormat::Exr) {
    return join("SetView.file_format ", num(static_cast<std::uint64_t>(m.file_format)),
                " unknown (0 PNG, 1 EXR)");
  }
  CHECK(text("SetView.quality_preset", m.quality_preset, kMaxPresetBytes, TextKind::Name));
  return {};
}

Problem check_utc(std::string_view field, double t) {
  return closed_open(field, t, kMinUtc_s, kMaxUtc_s);
}

Problem check_pose(const Pose& p, std::string_view prefix) {
  const std::string pre(prefix);
  CHECK(finite(join(pre, "sim_time_s"), p.sim_time_s));
  if (p.utc_unix_s) CHECK(check_utc(join(pre, "utc_unix_s"), *p.utc_unix_s));
  CHECK(closed(join(pre, "lat_deg"), p.lat_deg, -90.0, 90.0));
  CHECK(closed(join(pre, "lon_deg"), p.lon_deg, -180.0, 180.0));
  CHECK(closed(join(pre, "alt_m"), p.alt_m, kMinAltitude_m, kMaxAltitude_m));
  CHECK(closed(join(pre, "heading_deg"), p.heading_deg, -kMaxAbsHeading_deg, kMaxAbsHeading_deg));
  CHECK(closed(join(pre, "pitch_deg"), p.pitch_deg, -kMaxAbsPitch_deg, kMaxAbsPitch_deg));
  CHECK(closed(join(pre, "roll_deg"), p.roll_deg, -kMaxAbsRoll_deg, kMaxAbsRoll_deg));
  if (p.velocity_enu) {
    const VelocityEnu& v = *p.velocity_enu;
    CHECK(finite(join(pre, "velocity_enu.east_mps"), v.east_mps));
    CHECK(finite(join(pre, "velocity_enu.north_mps"), v.north_mps));
    CHECK(finite(join(pre, "velocity_enu.up_mps"), v.up_mps));
    const double speed = std::hypot(v.east_mps, v.north_mps, v.up_mps);
    if (!(speed <= kMaxSpeed_mps)) {
      return join(pre, "velocity_enu speed ", num(speed), " m/s above ", num(kMaxSpeed_mps));
    }
  }
  CHECK(known_bits(join(pre, "flags"), p.flags, pose_flag::kAll));
  return {};
}

Problem check(const Pose& m) { return check_pose(m, "Pose."); }

Problem check(const SetTime& m) { return check_utc("SetTime.utc_unix_s", m.utc_unix_s); }

Problem check_layer(const CloudLayer& l, const std::string& pre) {
  CHECK(count_in(join(pre, "type"), l.type, kMinCloudType, kMaxCloudType));
  CHECK(closed(join(pre, "base_m"), l.base_m, kMinLayerBase_m, kMaxLayerTop_m));
  CHECK(closed(join(pre, "top_m"), l.top_m, kMinLayerBase_m, kMaxLayerTop_m));
  if (l.top_m - l.base_m < kMinLayerThickness_m) {
    return join(pre, "top_m ", num(l.top_m), " less than ", num(kMinLayerThickness_m),
                " m above base_m ", num(l.base_m));
  }
  CHECK(closed(join(pre, "coverage"), l.coverage, 0.0, 1.0));
  CHECK(closed(join(pre, "density_scale"), l.density_scale, 0.0, kMaxDensityScale));
  CHECK(closed(join(pre, "droplet_diameter_um"), l.droplet_diameter_um, kMinDropletDiameter_um,
               kMaxDropletDiameter_um));
  CHECK(finite(join(pre, "wind_east_mps"), l.wind_east_mps));
  CHECK(finite(join(pre, "wind_north_mps"), l.wind_north_mps));
  if (l.coverage_channel < -1 || l.coverage_channel > 3)
    return join(pre, "coverage_channel ", num(l.coverage_channel), " out of range [-1, 3]");
  const double speed = std::hypot(l.wind_east_mps, l.wind_north_mps);
  if (!(speed <= kMaxWindSpeed_mps)) {
    return join(pre, "wind speed ", num(speed), " m/s above ", num(kMaxWindSpeed_mps));
  }
  return {};
}

Problem check(const WeatherLayers& m) {
  if (m.layers.size() > kMaxLayers) {
    return join("WeatherLayers.layers has ", num(m.layers.size()), " layers (at most ",
                num(kMaxLayers), ")");
  }
  if (m.ground_albedo) CHECK(closed("WeatherLayers.ground_albedo", *m.ground_albedo, 0.0, 1.0));
  if (m.visibility_m) {  // m; below the range is fog, which the haze does not draw
    Problem p = closed("WeatherLayers.visibility_m", *m.visibility_m, weather::kMinVisibility_m, weather::kMaxVisibility_m);
    if (p && std::isfinite(*m.visibility_m))
      p = *m.visibility_m < weather::kMinVisibility_m ? join(*p, " m (below ", num(weather::kMinVisibility_m), " m is fog, not drawn)")
                                                      : join(*p, " m");
    if (p) return p;
  }
  for (std::size_t i = 0; i < m.layers.size(); ++i) {
    const std::string pre = join("WeatherLayers.layers[", num(i), "].");
    CHECK(check_layer(m.layers[i], pre));
    if (i > 0 && m.layers[i].base_m < m.layers[i - 1].top_m) {
      const bool unsorted = m.layers[i].base_m < m.layers[i - 1].base_m;
      return join(pre, "base_m ", num(m.layers[i].base_m), " below layers[", num(i - 1), "].top_m ",
                  num(m.layers[i - 1].top_m),
                  unsorted ? " (layers must be sorted by base_m)" : " (layers overlap)");
    }
  }
  return {};
}

// A tile is judged by the weather module's rules (weather/map_tile.h), the ones the
// timeline and the renderer hold every tile to, with the fields named "WeatherMapTile.":
// bounds, size up to kMaxTileSize (= weather::kMaxTileTexels), channels, valid-at time
// finite, then the values. The protocol's own rule, the UTC range every time in a message
// has, goes between the fields and the values, so the first problem named is the same as
// when this function held its own copy of the rules.
Problem check(const WeatherMapTile& m) {
  static_assert(tile_channel::kAll == weather::kAllTileChannels);
  const weather::MapTileHeader header = to_tile_header(m);
  if (std::string p = weather::tile_header_problem(header, "WeatherMapTile."); !p.empty()) return p;
  CHECK(check_utc("WeatherMapTile.valid_at_utc_s", m.valid_at_utc_s));
  if (std::string p = weather::tile_data_problem(header, m.data, "WeatherMapTile."); !p.empty()) return p;
  return {};
}

Problem check(const RenderRequest& m) {
  if (m.request_id == 0) return std::string("RenderRequest.request_id is 0 (must be non-zero)");
  return {};
}

Problem check(const FrameReady& m) {
  CHECK(check_pose(m.pose, "FrameReady.pose."));
  CHECK(finite("FrameReady.sim_time_s", m.sim_time_s));
  CHECK(count_in("FrameReady.width", m.width, 1, kMaxImageSize));
  CHECK(count_in("FrameReady.height", m.height, 1, kMaxImageSize));
  CHECK(nonnegative("FrameReady.render_ms", m.render_ms));
  CHECK(nonnegative("FrameReady.latency_ms", m.latency_ms));
  if (m.file_path) {
    if (m.file_path->empty()) return std::string("FrameReady.file_path is present but empty");
    CHECK(text("FrameReady.file_path", *m.file_path, kMaxPathBytes, TextKind::OneLine));
  }
  return {};
}

Problem check(const Error& m) {
  // Codes outside the enum may come from a newer minor version and are accepted.
  CHECK(text("Error.text", m.text, kMaxErrorTextBytes, TextKind::OneLine));
  return {};
}

Problem check(const StatsRequest&) { return {}; }

Problem check(const Stats& m) {
  CHECK(nonnegative("Stats.fps", m.fps));
  CHECK(nonnegative("Stats.frame_in_progress_ms", m.frame_in_progress_ms));
  if (m.poses_dropped > m.poses_received) {
    return join("Stats.poses_dropped ", num(m.poses_dropped), " exceeds poses_received ",
                num(m.poses_received));
  }
  return {};
}

#undef CHECK

}  // namespace

std::optional<std::string> validate(const Message& m) {
  return std::visit([](const auto& v) { return check(v); }, m);
}

}  // namespace cloudsvc::protocol
