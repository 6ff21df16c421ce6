// The IG's answers to a host that go with the next Start of Frame: one IG Message for each
// packet or datagram the IG did not use (cigi_datagram.h, Rejection) and for each note about
// the host's weather. A host -> IG datagram can hold many bad packets and a host can send
// many datagrams per frame, so what waits is bounded: past kMaxPending messages the rest are
// counted, and one last message says how many were not sent.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "protocol/cigi/cigi_bytes.h"
#include "protocol/cigi/cigi_packets.h"

namespace cloudsvc::cigi {

class IgMessageOutbox {
 public:
  // IG Messages after one Start of Frame: 32 x 104 bytes keeps the datagram under 3.4 kB.
  static constexpr std::size_t kMaxPending = 32;

  // Queues a message (cut to kMaxIgMessageText bytes when written).
  void add(std::string text);
  bool empty() const { return pending_.empty() && unsent_ == 0; }

  // The IG -> host datagram: `sof`, then the waiting messages in the order added (the last
  // one "N more messages not sent ..." when some were over the bound); empties the outbox.
  std::vector<std::uint8_t> datagram(const StartOfFrame& sof, ByteOrder order);

  std::uint64_t added() const { return added_; }    // every message ever added
  std::uint64_t unsent() const { return unsent_total_; }  // of those, not sent (over the bound)

 private:
  std::vector<std::string> pending_;
  std::size_t unsent_ = 0;  // over the bound since the last datagram
  std::uint16_t next_id_ = 1;
  std::uint64_t added_ = 0, unsent_total_ = 0;
};

}  // namespace cloudsvc::cigi
