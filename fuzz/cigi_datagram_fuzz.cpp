// Fuzz target: the CIGI 3.3 datagram readers (protocol/cigi/cigi_datagram.h), the first thing
// the IG does with every UDP datagram a host sends, and sim_client's reader of the IG's
// answers. Invariants checked besides the sanitizers':
//  - an unusable datagram yields no packets and one rejection saying why;
//  - every packet kept passed its checks, and written again in the datagram's byte order
//    (after its IG Control) it reads back to the same packets with no rejection;
//  - every rejection has a reason and the offset of a packet inside the datagram;
//  - the IG -> host reader keeps message texts within the packet and its 99-byte limit.
#include <cstddef>
#include <cstdint>
#include <span>

#include "fuzz/fuzz_check.h"
#include "protocol/cigi/cigi_checks.h"
#include "protocol/cigi/cigi_datagram.h"

using namespace cloudsvc::cigi;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  const HostDatagram d = read_host_datagram(bytes);
  for (const Rejection& r : d.rejections) {
    FUZZ_CHECK(!r.reason.empty(), "a rejection says why");
    FUZZ_CHECK(r.offset < size || size == 0, "a rejection points into the datagram");
  }
  if (!d.usable) {
    FUZZ_CHECK(d.packets.empty() && d.rejections.size() == 1, "an unusable datagram: nothing used, one reason");
  } else {
    FUZZ_CHECK(check(d.ig_control).empty(), "a usable datagram's IG Control passed its checks");
    for (const HostPacket& p : d.packets)
      FUZZ_CHECK(std::visit([](const auto& packet) { return check(packet).empty(); }, p), "a kept packet passed its checks");
    DatagramWriter again(d.order);
    again.add(d.ig_control);
    for (const HostPacket& p : d.packets) again.add(p);
    const HostDatagram back = read_host_datagram(again.bytes());
    FUZZ_CHECK(back.usable && back.rejections.empty(), "kept packets write and read again without a rejection");
    FUZZ_CHECK(back.packets == d.packets && back.ig_control == d.ig_control, "kept packets survive a write and a read");
  }
  const IgDatagram g = read_ig_datagram(bytes);
  for (const IgMessage& m : g.messages) FUZZ_CHECK(m.text.size() <= 255 - 4, "a message text lies within its packet");
  if (!g.usable) FUZZ_CHECK(g.messages.empty(), "an unusable IG datagram: no messages");
  return 0;
}
