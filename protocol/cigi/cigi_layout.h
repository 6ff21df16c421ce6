// One definition of each CIGI 3.3 packet's layout (cigi_packets.h), used both ways: the
// same function reads a packet's fields (FieldsIn) and writes them (FieldsOut), so the
// offsets and bits of a packet are written down once. The header (opcode, size) and the
// byte-swap magic are the caller's.
#pragma once

#include <cstddef>
#include <cstdint>

#include "protocol/cigi/cigi_bytes.h"
#include "protocol/cigi/cigi_packets.h"

namespace cloudsvc::cigi::layout {

// Reads fields into references.
class FieldsIn {
 public:
  explicit FieldsIn(FieldReader r) : r_(r) {}
  void u8(std::size_t at, std::uint8_t& v) const { v = r_.u8(at); }
  void i8(std::size_t at, std::int8_t& v) const { v = r_.i8(at); }
  void u16(std::size_t at, std::uint16_t& v) const { v = r_.u16(at); }
  void u32(std::size_t at, std::uint32_t& v) const { v = r_.u32(at); }
  void f32(std::size_t at, float& v) const { v = r_.f32(at); }
  void f64(std::size_t at, double& v) const { v = r_.f64(at); }
  // `count` bits of byte `at` from bit `first` (0 = least significant).
  template <class T>
  void bits(std::size_t at, int first, int count, T& v) const {
    v = static_cast<T>((r_.u8(at) >> first) & ((1u << count) - 1u));
  }
  void flag(std::size_t at, int bit, bool& v) const { v = ((r_.u8(at) >> bit) & 1u) != 0; }

 private:
  FieldReader r_;
};

// Writes fields from (copies of) the values.
class FieldsOut {
 public:
  explicit FieldsOut(FieldWriter& w) : w_(w) {}
  void u8(std::size_t at, std::uint8_t v) { w_.u8(at, v); }
  void i8(std::size_t at, std::int8_t v) { w_.i8(at, v); }
  void u16(std::size_t at, std::uint16_t v) { w_.u16(at, v); }
  void u32(std::size_t at, std::uint32_t v) { w_.u32(at, v); }
  void f32(std::size_t at, float v) { w_.f32(at, v); }
  void f64(std::size_t at, double v) { w_.f64(at, v); }
  template <class T>
  void bits(std::size_t at, int first, int count, T v) {
    w_.or_u8(at, static_cast<std::uint8_t>((static_cast<unsigned>(v) & ((1u << count) - 1u)) << first));
  }
  void flag(std::size_t at, int bit, bool v) { w_.or_u8(at, static_cast<std::uint8_t>(v ? 1u << bit : 0u)); }

 private:
  FieldWriter& w_;
};

// Packet sizes, bytes.
inline constexpr std::uint8_t kIgControlSize = 24, kEntityControlSize = 48, kViewControlSize = 32,
                              kViewDefinitionSize = 32, kCelestialSphereControlSize = 16,
                              kAtmosphereControlSize = 32, kEnvironmentalRegionControlSize = 48,
                              kWeatherControlSize = 56, kStartOfFrameSize = 24;
inline constexpr std::size_t kMagicOffset = 6;  // u16 of IG Control and Start of Frame

template <class Io>
void fields(Io& io, IgControl& p) {
  io.u8(2, p.major_version);
  io.i8(3, p.database);
  io.bits(4, 0, 2, p.mode);
  io.flag(4, 2, p.timestamp_valid);
  io.flag(4, 3, p.extrapolation);
  io.bits(4, 4, 4, p.minor_version);
  io.u32(8, p.host_frame);
  io.u32(12, p.timestamp);
  io.u32(16, p.last_ig_frame);
}

template <class Io>
void fields(Io& io, EntityControl& p) {
  io.u16(2, p.entity_id);
  io.bits(4, 0, 2, p.state);
  io.flag(4, 2, p.attached);
  io.u16(8, p.entity_type);
  io.u16(10, p.parent_id);
  io.f32(12, p.roll_deg);
  io.f32(16, p.pitch_deg);
  io.f32(20, p.yaw_deg);
  io.f64(24, p.lat_deg);
  io.f64(32, p.lon_deg);
  io.f64(40, p.alt_m);
}

template <class Io>
void fields(Io& io, ViewControl& p) {
  io.u16(2, p.view_id);
  io.u8(4, p.group_id);
  io.bits(5, 0, 6, p.enable);
  io.u16(6, p.entity_id);
  io.f32(8, p.x_m);
  io.f32(12, p.y_m);
  io.f32(16, p.z_m);
  io.f32(20, p.roll_deg);
  io.f32(24, p.pitch_deg);
  io.f32(28, p.yaw_deg);
}

template <class Io>
void fields(Io& io, ViewDefinition& p) {
  io.u16(2, p.view_id);
  io.u8(4, p.group_id);
  io.bits(5, 0, 6, p.enable);
  io.bits(5, 6, 2, p.mirror);
  io.bits(6, 0, 3, p.pixel_replication);
  io.flag(6, 3, p.orthographic);
  io.flag(6, 4, p.reorder);
  io.bits(6, 5, 3, p.view_type);
  io.f32(8, p.near_m);
  io.f32(12, p.far_m);
  io.f32(16, p.left_deg);
  io.f32(20, p.right_deg);
  io.f32(24, p.top_deg);
  io.f32(28, p.bottom_deg);
}

template <class Io>
void fields(Io& io, CelestialSphereControl& p) {
  io.u8(2, p.hour);
  io.u8(3, p.minute);
  io.flag(4, 0, p.ephemeris);
  io.flag(4, 1, p.sun);
  io.flag(4, 2, p.moon);
  io.flag(4, 3, p.stars);
  io.flag(4, 4, p.date_valid);
  io.u32(8, p.date);
  io.f32(12, p.star_intensity_pct);
}

template <class Io>
void fields(Io& io, AtmosphereControl& p) {
  io.flag(2, 0, p.model_enable);
  io.u8(3, p.humidity_pct);
  io.f32(4, p.air_temperature_c);
  io.f32(8, p.visibility_m);
  io.f32(12, p.wind_horizontal_mps);
  io.f32(16, p.wind_vertical_mps);
  io.f32(20, p.wind_direction_deg);
  io.f32(24, p.pressure_hpa);
}

template <class Io>
void fields(Io& io, EnvironmentalRegionControl& p) {
  io.u16(2, p.region_id);
  io.bits(4, 0, 2, p.state);
  io.bits(4, 2, 4, p.merge);
  io.f64(8, p.lat_deg);
  io.f64(16, p.lon_deg);
  io.f32(24, p.size_x_m);
  io.f32(28, p.size_y_m);
  io.f32(32, p.corner_radius_m);
  io.f32(36, p.rotation_deg);
  io.f32(40, p.transition_perimeter_m);
}

template <class Io>
void fields(Io& io, WeatherControl& p) {
  io.u16(2, p.entity_or_region_id);
  io.u8(4, p.layer_id);
  io.u8(5, p.humidity_pct);
  io.flag(6, 0, p.enabled);
  io.flag(6, 1, p.scud);
  io.flag(6, 2, p.random_winds);
  io.flag(6, 3, p.random_lightning);
  io.bits(6, 4, 4, p.cloud_type);
  io.bits(7, 0, 2, p.scope);
  io.bits(7, 2, 3, p.severity);
  io.f32(8, p.air_temperature_c);
  io.f32(12, p.visibility_m);
  io.f32(16, p.scud_frequency_pct);
  io.f32(20, p.coverage_pct);
  io.f32(24, p.base_elevation_m);
  io.f32(28, p.thickness_m);
  io.f32(32, p.transition_band_m);
  io.f32(36, p.wind_horizontal_mps);
  io.f32(40, p.wind_vertical_mps);
  io.f32(44, p.wind_direction_deg);
  io.f32(48, p.pressure_hpa);
  io.f32(52, p.aerosol_gpm3);
}

template <class Io>
void fields(Io& io, StartOfFrame& p) {
  io.u8(2, p.major_version);
  io.i8(3, p.database);
  io.u8(4, p.ig_status);
  io.bits(5, 0, 2, p.mode);
  io.flag(5, 2, p.timestamp_valid);
  io.flag(5, 3, p.host_earth_model);
  io.bits(5, 4, 4, p.minor_version);
  io.u32(8, p.ig_frame);
  io.u32(12, p.timestamp);
  io.u32(16, p.last_host_frame);
}

}  // namespace cloudsvc::cigi::layout
