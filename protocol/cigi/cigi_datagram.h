// CIGI datagrams in and out (cigi_packets.h): reading a host's message with every check the
// IG makes before it uses a packet, and writing messages in either byte order (the IG's
// answers; a host's messages for sim_client and tests).
//
// Checks, in order (docs/CIGI.md, "Bad datagrams"):
//   - the datagram: at least an IG Control (24 bytes) first, major version 3, minor 2 or 3,
//     the byte-swap magic 0x8000 in either byte order; otherwise nothing of it is used;
//   - each packet: its size (at least 2, not past the datagram's end; a packet whose size
//     lies past the end ends the datagram there), its opcode (known packets of the wrong
//     size and unknown opcodes are skipped by their size), then its fields (NaN, infinities
//     and values out of the standard's ranges). A packet that fails is not used at all.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "protocol/cigi/cigi_bytes.h"
#include "protocol/cigi/cigi_packets.h"

namespace cloudsvc::cigi {

// A packet (or the whole datagram) not used, and why, in one line.
struct Rejection {
  std::size_t offset = 0;   // of the packet in the datagram, bytes
  std::uint8_t opcode = 0;  // 0 when the datagram itself is unusable
  std::string reason;       // e.g. "Entity Control at byte 24: lat_deg 95 out of range [-90, 90]"
};

// A host -> IG datagram as read.
struct HostDatagram {
  bool usable = false;             // false: nothing is used (rejections says why)
  ByteOrder order = ByteOrder::Big;
  IgControl ig_control;
  std::vector<HostPacket> packets;  // the honoured packets that passed their checks, in order
  std::size_t ignored = 0;          // packets accepted and ignored (other entities' control,
                                    // component controls, other known or user-defined opcodes)
  std::vector<Rejection> rejections;
};
HostDatagram read_host_datagram(std::span<const std::uint8_t> datagram);

// An IG -> host datagram as read (sim_client cigi, tests).
struct IgDatagram {
  bool usable = false;
  ByteOrder order = ByteOrder::Big;
  StartOfFrame start_of_frame;
  std::vector<IgMessage> messages;
  std::size_t ignored = 0;  // other IG -> host packets
  std::vector<Rejection> rejections;
};
IgDatagram read_ig_datagram(std::span<const std::uint8_t> datagram);

// Writes packets one after another into a datagram in one byte order. The first packet
// written should be IG Control (host) or Start of Frame (IG).
class DatagramWriter {
 public:
  explicit DatagramWriter(ByteOrder order = kNativeOrder) : order_(order) {}
  void add(const IgControl& p);
  void add(const EntityControl& p);
  void add(const ViewControl& p);
  void add(const ViewDefinition& p);
  void add(const CelestialSphereControl& p);
  void add(const AtmosphereControl& p);
  void add(const EnvironmentalRegionControl& p);
  void add(const WeatherControl& p);
  void add(const StartOfFrame& p);
  void add(const IgMessage& p);  // text cut to kMaxIgMessageText bytes
  void add(const HostPacket& p);
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  ByteOrder order_;
  std::vector<std::uint8_t> bytes_;
};

// The name of a packet's opcode for messages ("Entity Control", "opcode 77").
std::string packet_name(std::uint8_t opcode);

}  // namespace cloudsvc::cigi
