// The IG's messages to a CIGI host (protocol/cigi/cigi_ig_messages.h), read back as a host
// reads them (cigi_datagram.h) in both byte orders: the Start of Frame goes out as given,
// messages arrive whole, in order and once, an over-long text is cut without spoiling the
// datagram, and a flood of messages (a host sending many bad packets) gives a bounded
// datagram whose last message tells the operator how many were not sent.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "protocol/cigi/cigi_datagram.h"
#include "protocol/cigi/cigi_ig_messages.h"

namespace cloudsvc::cigi {
namespace {

constexpr ByteOrder kOrders[] = {ByteOrder::Big, ByteOrder::Little};

StartOfFrame start_of_frame(std::uint32_t ig_frame) {
  StartOfFrame sof;
  sof.database = 2;
  sof.mode = IgMode::Debug;
  sof.timestamp_valid = true;
  sof.timestamp = 987654321;
  sof.ig_frame = ig_frame;
  sof.last_host_frame = ig_frame - 3;
  return sof;
}

IgDatagram read(const std::vector<std::uint8_t>& bytes) {
  IgDatagram d = read_ig_datagram(bytes);
  EXPECT_TRUE(d.usable) << (d.rejections.empty() ? "" : d.rejections.front().reason);
  EXPECT_TRUE(d.rejections.empty()) << d.rejections.front().reason;
  return d;
}

TEST(CigiIgMessages, AnEmptyOutboxSendsJustTheStartOfFrame) {
  for (ByteOrder order : kOrders) {
    IgMessageOutbox box;
    EXPECT_TRUE(box.empty());
    const StartOfFrame sof = start_of_frame(1234567);
    const std::vector<std::uint8_t> bytes = box.datagram(sof, order);
    const IgDatagram d = read(bytes);
    EXPECT_EQ(d.order, order);
    EXPECT_EQ(d.start_of_frame, sof);
    EXPECT_EQ(d.start_of_frame.ig_frame, 1234567u);
    EXPECT_EQ(d.start_of_frame.last_host_frame, 1234564u);
    EXPECT_EQ(d.start_of_frame.mode, IgMode::Debug);
    EXPECT_EQ(d.start_of_frame.timestamp, 987654321u);
    EXPECT_TRUE(d.messages.empty());
    EXPECT_EQ(d.ignored, 0u);
    EXPECT_EQ(bytes.size(), 24u) << "the Start of Frame alone";
    EXPECT_EQ(box.added(), 0u);
    EXPECT_EQ(box.unsent(), 0u);
  }
}

TEST(CigiIgMessages, MessagesGoOutInOrderOnceWithRisingIds) {
  for (ByteOrder order : kOrders) {
    IgMessageOutbox box;
    const std::vector<std::string> texts = {"Entity Control at byte 24: lat_deg 95 out of range [-90, 90]",
                                            "unknown packet opcode 77 at byte 72", "", "weather: layer 2 lies within layer 1"};
    for (const std::string& t : texts) box.add(t);
    EXPECT_FALSE(box.empty());
    EXPECT_EQ(box.added(), texts.size());

    const IgDatagram d = read(box.datagram(start_of_frame(10), order));
    EXPECT_EQ(d.start_of_frame, start_of_frame(10));
    ASSERT_EQ(d.messages.size(), texts.size());
    for (std::size_t i = 0; i < texts.size(); ++i) {
      EXPECT_EQ(d.messages[i].text, texts[i]) << i;
      if (i > 0) {
        EXPECT_GT(d.messages[i].message_id, d.messages[i - 1].message_id) << i;
      }
    }
    EXPECT_TRUE(box.empty()) << "the datagram takes the messages";
    EXPECT_EQ(box.unsent(), 0u);

    // The next frame: no message again.
    const IgDatagram again = read(box.datagram(start_of_frame(11), order));
    EXPECT_EQ(again.start_of_frame.ig_frame, 11u);
    EXPECT_TRUE(again.messages.empty());

    // Later messages keep rising ids: the host can tell them from the earlier ones.
    box.add("later");
    const IgDatagram later = read(box.datagram(start_of_frame(12), order));
    ASSERT_EQ(later.messages.size(), 1u);
    EXPECT_EQ(later.messages[0].text, "later");
    EXPECT_GT(later.messages[0].message_id, d.messages.back().message_id);
    EXPECT_EQ(box.added(), texts.size() + 1);
  }
}

TEST(CigiIgMessages, ALongMessageIsCutAndTheDatagramStillReads) {
  for (ByteOrder order : kOrders) {
    IgMessageOutbox box;
    std::string text;
    for (int i = 0; text.size() < 250; ++i) text += std::to_string(i) + ",";
    box.add(text);
    box.add("after");
    const std::vector<std::uint8_t> bytes = box.datagram(start_of_frame(5), order);
    const IgDatagram d = read(bytes);
    ASSERT_EQ(d.messages.size(), 2u);
    EXPECT_EQ(d.messages[0].text, text.substr(0, kMaxIgMessageText));
    EXPECT_EQ(d.messages[0].text.size(), 99u);
    EXPECT_EQ(d.messages[1].text, "after") << "the packet after the cut one is read where it starts";
    EXPECT_EQ(bytes.size(), 24u + 104u + 16u);
  }
}

TEST(CigiIgMessages, AFloodIsBoundedAndTheLastMessageCountsTheRest) {
  constexpr std::size_t kAdded = 100;
  constexpr std::size_t kMax = IgMessageOutbox::kMaxPending;
  static_assert(kAdded > kMax);
  for (ByteOrder order : kOrders) {
    IgMessageOutbox box;
    for (std::size_t i = 0; i < kAdded; ++i) box.add("Weather Control at byte " + std::to_string(24 + 56 * i) + ": bad " + std::to_string(i));
    EXPECT_EQ(box.added(), kAdded);
    const std::vector<std::uint8_t> bytes = box.datagram(start_of_frame(9), order);
    EXPECT_LT(bytes.size(), 4096u) << "the bound keeps the datagram small whatever the host sends";
    const IgDatagram d = read(bytes);
    ASSERT_EQ(d.messages.size(), kMax);
    for (std::size_t i = 0; i + 1 < kMax; ++i)
      EXPECT_EQ(d.messages[i].text, "Weather Control at byte " + std::to_string(24 + 56 * i) + ": bad " + std::to_string(i)) << i;
    const std::size_t not_sent = kAdded - (kMax - 1);
    EXPECT_EQ(d.messages.back().text.rfind(std::to_string(not_sent) + " more messages not sent", 0), 0u)
        << d.messages.back().text;
    EXPECT_EQ(box.unsent(), not_sent);
    EXPECT_EQ(box.added(), kAdded);
    EXPECT_TRUE(box.empty());

    // The count is not repeated with the next frame.
    const IgDatagram next = read(box.datagram(start_of_frame(10), order));
    EXPECT_TRUE(next.messages.empty());
    EXPECT_EQ(box.unsent(), not_sent) << "the total so far";
  }
}

}  // namespace
}  // namespace cloudsvc::cigi
