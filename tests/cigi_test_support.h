// A CIGI host's datagram made in tests: IG Control and packets written as a host sends them,
// then read as the IG reads them (protocol/cigi/cigi_datagram.h).
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "protocol/cigi/cigi_datagram.h"

namespace cloudsvc::cigi {

inline HostDatagram host_datagram(const std::vector<HostPacket>& packets, std::uint32_t host_frame = 1,
                                  IgMode mode = IgMode::Operate, ByteOrder order = ByteOrder::Big) {
  DatagramWriter w(order);
  IgControl c;
  c.host_frame = host_frame;
  c.mode = mode;
  w.add(c);
  for (const HostPacket& p : packets) w.add(p);
  HostDatagram d = read_host_datagram(w.bytes());
  EXPECT_TRUE(d.rejections.empty()) << d.rejections.front().reason;
  return d;
}

}  // namespace cloudsvc::cigi
