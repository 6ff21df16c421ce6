// The IG's pending IG Messages (cigi_ig_messages.h).
#include "protocol/cigi/cigi_ig_messages.h"

#include "protocol/cigi/cigi_datagram.h"

namespace cloudsvc::cigi {

void IgMessageOutbox::add(std::string text) {
  ++added_;
  // One place is kept for the message that counts the unsent ones.
  if (pending_.size() + 1 < kMaxPending) {
    pending_.push_back(std::move(text));
  } else {
    ++unsent_;
    ++unsent_total_;
  }
}

std::vector<std::uint8_t> IgMessageOutbox::datagram(const StartOfFrame& sof, ByteOrder order) {
  DatagramWriter w(order);
  w.add(sof);
  if (unsent_ > 0)
    pending_.push_back(std::to_string(unsent_) + " more messages not sent (at most " + std::to_string(kMaxPending) +
                       " per Start of Frame)");
  for (std::string& text : pending_) w.add(IgMessage{next_id_++, std::move(text)});
  pending_.clear();
  unsent_ = 0;
  return w.bytes();
}

}  // namespace cloudsvc::cigi
