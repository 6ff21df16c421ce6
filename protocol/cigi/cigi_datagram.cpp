// Reading and writing CIGI datagrams (cigi_datagram.h).
#include "protocol/cigi/cigi_datagram.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <type_traits>
#include <utility>

#include "protocol/cigi/cigi_checks.h"
#include "protocol/cigi/cigi_layout.h"

namespace cloudsvc::cigi {
namespace {

using layout::FieldsIn;
using layout::FieldsOut;

// The sizes of the CIGI 3.3 host -> IG packets by opcode 1..35, bytes (0: variable, the
// symbol definitions 30-32); those the IG does not draw from are accepted and ignored when
// of their size.
constexpr std::uint8_t kHostPacketSizes[36] = {
    0,  24, 48, 24, 32, 16, 32, 16, 32, 16, 32, 48, 56, 24, 32, 8,  32, 24,
    8,  24, 24, 32, 40, 48, 32, 64, 56, 8,  32, 56, 0,  0,  0,  8,  40, 32};
constexpr std::uint8_t kLastHostOpcode = 35;
constexpr std::uint8_t kLastIgOpcode = 117;

// Fields a packet's enable bits leave out are not used: they read as 0, whatever the host
// put there (NaN included), so that they pass the checks and compare equal.
void clear_disabled(ViewControl& p) {
  using namespace view_enable;
  for (auto [bit, field] : {std::pair{kX, &p.x_m}, std::pair{kY, &p.y_m}, std::pair{kZ, &p.z_m},
                            std::pair{kRoll, &p.roll_deg}, std::pair{kPitch, &p.pitch_deg}, std::pair{kYaw, &p.yaw_deg}})
    if (!(p.enable & bit)) *field = 0.0f;
}
void clear_disabled(ViewDefinition& p) {
  using namespace definition_enable;
  for (auto [bit, field] : {std::pair{kNear, &p.near_m}, std::pair{kFar, &p.far_m}, std::pair{kLeft, &p.left_deg},
                            std::pair{kRight, &p.right_deg}, std::pair{kTop, &p.top_deg}, std::pair{kBottom, &p.bottom_deg}})
    if (!(p.enable & bit)) *field = 0.0f;
}
template <class P>
void clear_disabled(P&) {}

template <class P>
P read_fields(std::span<const std::uint8_t> packet, ByteOrder order) {
  P p;
  FieldsIn in(FieldReader(packet, order));
  layout::fields(in, p);
  clear_disabled(p);
  return p;
}

template <class P>
void write_fields(std::vector<std::uint8_t>& out, std::uint8_t op, std::uint8_t size, ByteOrder order, P p) {
  FieldWriter w(out, op, size, order);
  FieldsOut fo(w);
  layout::fields(fo, p);
  if (op == opcode::kIgControl || op == opcode::kStartOfFrame) w.u16(layout::kMagicOffset, kByteSwapMagic);
}

// The sender's byte order from the magic number at bytes 6-7 of the first packet.
std::optional<ByteOrder> order_of(std::span<const std::uint8_t> d) {
  if (d[layout::kMagicOffset] == 0x80 && d[layout::kMagicOffset + 1] == 0x00) return ByteOrder::Big;
  if (d[layout::kMagicOffset] == 0x00 && d[layout::kMagicOffset + 1] == 0x80) return ByteOrder::Little;
  return std::nullopt;
}

std::string hex4(unsigned v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%04x", v & 0xffffu);
  return buf;
}

// The checks of a datagram's first packet, shared by both directions: present, of its
// size, major version 3, minor 2 or later, a byte-swap magic. Empty when it passes.
std::string first_packet_problem(std::span<const std::uint8_t> d, std::uint8_t op, std::uint8_t size, int minor_byte) {
  const std::string name = packet_name(op);
  if (d.size() < 2 || d[0] != op)
    return "the datagram does not start with " + name + " (opcode " + std::to_string(op) + ")";
  if (d[1] != size || d.size() < size)
    return name + " of " + std::to_string(d[1]) + " bytes in a datagram of " + std::to_string(d.size()) +
           " (CIGI 3.2 and 3.3: " + std::to_string(size) + ")";
  if (d[2] != kMajorVersion)
    return "CIGI major version " + std::to_string(d[2]) + " (this IG speaks CIGI 3.3)";
  if ((d[minor_byte] >> 4) < kOldestMinorVersion)
    return "CIGI minor version 3." + std::to_string(d[minor_byte] >> 4) + " (this IG speaks CIGI 3.2 and 3.3)";
  if (!order_of(d))
    return "byte-swap magic " + hex4((d[6] << 8) | d[7]) + " (expected 8000 in either byte order)";
  return {};
}

// Walks the packets after the first: each (offset, opcode, bytes) whose header is sound; a
// header that cannot be sound ends the walk with a rejection.
template <class Visit>
void walk_packets(std::span<const std::uint8_t> d, std::size_t at, std::vector<Rejection>& rejections, Visit visit) {
  while (at < d.size()) {
    const std::size_t left = d.size() - at;
    if (left < 2) {
      rejections.push_back({at, d[at], std::to_string(left) + " byte after the last packet, shorter than a packet header"});
      return;
    }
    const std::uint8_t op = d[at], size = d[at + 1];
    if (size < 2 || size > left) {
      rejections.push_back({at, op, packet_name(op) + " at byte " + std::to_string(at) + ": size " + std::to_string(size) +
                                        (size < 2 ? " (a packet is at least 2 bytes)"
                                                  : " runs past the datagram's end (" + std::to_string(left) + " bytes left)") +
                                        "; the rest of the datagram is skipped"});
      return;
    }
    visit(at, op, d.subspan(at, size));
    at += size;
  }
}

}  // namespace

std::string packet_name(std::uint8_t op) {
  switch (op) {
    case opcode::kIgControl: return "IG Control";
    case opcode::kEntityControl: return "Entity Control";
    case opcode::kComponentControl: return "Component Control";
    case opcode::kShortComponentControl: return "Short Component Control";
    case opcode::kCelestialSphereControl: return "Celestial Sphere Control";
    case opcode::kAtmosphereControl: return "Atmosphere Control";
    case opcode::kEnvironmentalRegionControl: return "Environmental Region Control";
    case opcode::kWeatherControl: return "Weather Control";
    case opcode::kViewControl: return "View Control";
    case opcode::kViewDefinition: return "View Definition";
    case opcode::kStartOfFrame: return "Start of Frame";
    case opcode::kIgMessage: return "IG Message";
    default: return "opcode " + std::to_string(op);
  }
}

HostDatagram read_host_datagram(std::span<const std::uint8_t> d) {
  HostDatagram out;
  if (std::string problem = first_packet_problem(d, opcode::kIgControl, layout::kIgControlSize, 4); !problem.empty()) {
    out.rejections.push_back({0, d.empty() ? std::uint8_t{0} : d[0], problem});
    return out;
  }
  out.order = *order_of(d);
  out.ig_control = read_fields<IgControl>(d.first(layout::kIgControlSize), out.order);
  if (std::string problem = check(out.ig_control); !problem.empty()) {
    out.rejections.push_back({0, opcode::kIgControl, "IG Control: " + problem});
    return out;
  }
  out.usable = true;
  // A packet of a known size is read, checked, and kept or rejected as a whole.
  const auto take = [&]<class P>(std::size_t at, std::uint8_t op, std::span<const std::uint8_t> bytes, std::uint8_t size) {
    const std::string where = packet_name(op) + " at byte " + std::to_string(at);
    if (bytes.size() != size) {
      out.rejections.push_back({at, op, where + ": " + std::to_string(bytes.size()) + " bytes (CIGI 3.3: " +
                                            std::to_string(size) + "); skipped"});
      return;
    }
    P p = read_fields<P>(bytes, out.order);
    if constexpr (std::is_same_v<P, EntityControl>) {
      if (p.entity_id != 0) {  // other entities: accepted, not drawn
        ++out.ignored;
        return;
      }
    }
    if (std::string problem = check(p); !problem.empty()) {
      out.rejections.push_back({at, op, where + ": " + problem});
      return;
    }
    out.packets.emplace_back(std::move(p));
  };
  walk_packets(d, layout::kIgControlSize, out.rejections, [&](std::size_t at, std::uint8_t op, std::span<const std::uint8_t> bytes) {
    switch (op) {
      case opcode::kEntityControl: return take.template operator()<EntityControl>(at, op, bytes, layout::kEntityControlSize);
      case opcode::kViewControl: return take.template operator()<ViewControl>(at, op, bytes, layout::kViewControlSize);
      case opcode::kViewDefinition: return take.template operator()<ViewDefinition>(at, op, bytes, layout::kViewDefinitionSize);
      case opcode::kCelestialSphereControl:
        return take.template operator()<CelestialSphereControl>(at, op, bytes, layout::kCelestialSphereControlSize);
      case opcode::kAtmosphereControl:
        return take.template operator()<AtmosphereControl>(at, op, bytes, layout::kAtmosphereControlSize);
      case opcode::kEnvironmentalRegionControl:
        return take.template operator()<EnvironmentalRegionControl>(at, op, bytes, layout::kEnvironmentalRegionControlSize);
      case opcode::kWeatherControl: return take.template operator()<WeatherControl>(at, op, bytes, layout::kWeatherControlSize);
      case opcode::kIgControl:
        out.rejections.push_back({at, op, "IG Control at byte " + std::to_string(at) + ": a second IG Control in one datagram; skipped"});
        return;
      default: break;
    }
    if (op >= 1 && op <= kLastHostOpcode) {
      if (kHostPacketSizes[op] != 0 && bytes.size() != kHostPacketSizes[op]) {
        out.rejections.push_back({at, op, packet_name(op) + " at byte " + std::to_string(at) + ": " +
                                              std::to_string(bytes.size()) + " bytes (CIGI 3.3: " +
                                              std::to_string(kHostPacketSizes[op]) + "); skipped"});
        return;
      }
      ++out.ignored;  // a host packet the IG does not draw from
    } else if (op >= opcode::kFirstUserDefined) {
      ++out.ignored;  // user-defined
    } else if (op >= opcode::kStartOfFrame && op <= kLastIgOpcode) {
      out.rejections.push_back({at, op, packet_name(op) + " at byte " + std::to_string(at) + ": an IG -> host packet from the host; skipped"});
    } else {
      out.rejections.push_back({at, op, "unknown packet opcode " + std::to_string(op) + " at byte " + std::to_string(at) +
                                            " (" + std::to_string(bytes.size()) + " bytes); skipped"});
    }
  });
  return out;
}

IgDatagram read_ig_datagram(std::span<const std::uint8_t> d) {
  IgDatagram out;
  if (std::string problem = first_packet_problem(d, opcode::kStartOfFrame, layout::kStartOfFrameSize, 5); !problem.empty()) {
    out.rejections.push_back({0, d.empty() ? std::uint8_t{0} : d[0], problem});
    return out;
  }
  out.order = *order_of(d);
  out.start_of_frame = read_fields<StartOfFrame>(d.first(layout::kStartOfFrameSize), out.order);
  out.usable = true;
  walk_packets(d, layout::kStartOfFrameSize, out.rejections, [&](std::size_t at, std::uint8_t op, std::span<const std::uint8_t> bytes) {
    if (op != opcode::kIgMessage) {
      ++out.ignored;
      return;
    }
    if (bytes.size() < 5) {
      out.rejections.push_back({at, op, "IG Message at byte " + std::to_string(at) + ": " + std::to_string(bytes.size()) + " bytes, no room for text"});
      return;
    }
    IgMessage m;
    m.message_id = FieldReader(bytes, out.order).u16(2);
    const auto text = bytes.subspan(4);
    const auto end = std::find(text.begin(), text.end(), std::uint8_t{0});
    m.text.assign(text.begin(), end);
    out.messages.push_back(std::move(m));
  });
  return out;
}

void DatagramWriter::add(const IgControl& p) { write_fields(bytes_, opcode::kIgControl, layout::kIgControlSize, order_, p); }
void DatagramWriter::add(const EntityControl& p) { write_fields(bytes_, opcode::kEntityControl, layout::kEntityControlSize, order_, p); }
void DatagramWriter::add(const ViewControl& p) { write_fields(bytes_, opcode::kViewControl, layout::kViewControlSize, order_, p); }
void DatagramWriter::add(const ViewDefinition& p) { write_fields(bytes_, opcode::kViewDefinition, layout::kViewDefinitionSize, order_, p); }
void DatagramWriter::add(const CelestialSphereControl& p) {
  write_fields(bytes_, opcode::kCelestialSphereControl, layout::kCelestialSphereControlSize, order_, p);
}
void DatagramWriter::add(const AtmosphereControl& p) {
  write_fields(bytes_, opcode::kAtmosphereControl, layout::kAtmosphereControlSize, order_, p);
}
void DatagramWriter::add(const EnvironmentalRegionControl& p) {
  write_fields(bytes_, opcode::kEnvironmentalRegionControl, layout::kEnvironmentalRegionControlSize, order_, p);
}
void DatagramWriter::add(const WeatherControl& p) { write_fields(bytes_, opcode::kWeatherControl, layout::kWeatherControlSize, order_, p); }
void DatagramWriter::add(const StartOfFrame& p) { write_fields(bytes_, opcode::kStartOfFrame, layout::kStartOfFrameSize, order_, p); }

void DatagramWriter::add(const IgMessage& p) {
  const std::size_t n = std::min(p.text.size(), kMaxIgMessageText);
  const auto size = static_cast<std::uint8_t>((4 + n + 1 + 7) / 8 * 8);  // text, NUL, zero padding to 8
  FieldWriter w(bytes_, opcode::kIgMessage, size, order_);
  w.u16(2, p.message_id);
  w.bytes(4, p.text.data(), n);
}

void DatagramWriter::add(const HostPacket& p) {
  std::visit([this](const auto& packet) { add(packet); }, p);
}

}  // namespace cloudsvc::cigi
