// The shared-memory reader (protocol/shm/shm_frame_reader.h and the C ABI of
// protocol/shm/cloudsvc_shm.h) against rings this test lays out itself: a well-formed ring is
// read, and every size field of the ring header and of a slot header that disagrees with
// the mapped segment (products that wrap around 64 bits included) is refused with an
// error naming the field, never by reading outside the mapping.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "protocol/shm/cloudsvc_shm.h"
#include "protocol/shm/shm_frame_reader.h"
#include "protocol/shm/shm_name.h"
#include "shm_test_ring.h"

namespace cloudsvc {
namespace {

using test::TestRing;

// What opening the ring reports: the exception text of ShmFrameReader, "" when it opens.
std::string open_error(const std::string& name) {
  try {
    ShmFrameReader reader(name);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// The C ABI's refusal: its error text, "" when it opens.
std::string c_open_error(const std::string& name) {
  char err[512] = "";
  cloudsvc_shm_reader* r = cloudsvc_shm_open(name.c_str(), err, sizeof err);
  if (r) {
    cloudsvc_shm_close(r);
    return "";
  }
  return err;
}

// A consistent header: 2 slots of 16x32 pixels at 8 bytes per pixel (4096 pixel bytes),
// 12800 bytes of ring.
cloudsvc_shm_header good_header() {
  cloudsvc_shm_header h{};
  h.magic = CLOUDSVC_SHM_MAGIC;
  h.version = CLOUDSVC_SHM_VERSION;
  h.header_bytes = CLOUDSVC_SHM_HEADER_BYTES;
  h.slot_count = 2;
  h.slot_stride = CLOUDSVC_SHM_SLOT_HEADER_BYTES + 16 * 32 * 8;
  h.max_width = 16;
  h.max_height = 32;
  h.latest_frame = 1;
  h.latest_slot = 1;
  return h;
}
constexpr std::size_t kSegmentBytes = 16384;  // room for the good header's 12800-byte ring

// Opens a segment holding `h` through both readers and expects both to refuse it with a
// message containing every fragment.
void expect_refused(const char* what, const cloudsvc_shm_header& h, const std::vector<std::string>& fragments,
                    std::size_t segment_bytes = kSegmentBytes) {
  SCOPED_TRACE(what);
  TestRing ring("hostile", h, segment_bytes);
  const std::string cpp = open_error(ring.name());
  const std::string c = c_open_error(ring.name());
  ASSERT_FALSE(cpp.empty()) << "ShmFrameReader opened the ring";
  ASSERT_FALSE(c.empty()) << "cloudsvc_shm_open opened the ring";
  EXPECT_EQ(cpp.find('\n'), std::string::npos) << cpp;
  for (const std::string& f : fragments) {
    EXPECT_NE(cpp.find(f), std::string::npos) << cpp;
    EXPECT_NE(c.find(f), std::string::npos) << c;
  }
  EXPECT_NE(cpp.find(ring.name()), std::string::npos) << "names the segment: " << cpp;
}

TEST(ShmReader, ReadsAWellFormedRing) {
  TestRing ring("good", 4, 2);
  ShmFrameReader reader(ring.name());
  ShmFrame f;
  ASSERT_TRUE(reader.read_latest(0, f));
  EXPECT_EQ(f.info.frame_number, 5u);
  EXPECT_EQ(f.info.width, 4u);
  ASSERT_EQ(f.pixels.size(), 32u);
  EXPECT_EQ(f.pixels[31], 2u);  // slot 1
  EXPECT_FALSE(reader.read_latest(5, f));
  cloudsvc_shm_slot header{};
  EXPECT_TRUE(reader.read_latest_header(0, header));
  const TestRing header_only("good-header", good_header(), kSegmentBytes);
  EXPECT_EQ(open_error(header_only.name()), "") << "the reference header of the hostile cases is itself valid";
}

TEST(ShmReader, RefusesSlotStrideTimesSlotCountThatWrapsAround64Bits) {
  // 2^63 x 2 = 2^64 wraps to 0: without overflow checks the ring "fits" in 16 KiB and slot
  // 1 is read 2^63 bytes past the mapping (SIGSEGV in `sim_client watch`).
  cloudsvc_shm_header h = good_header();
  h.slot_stride = std::uint64_t{1} << 63;
  expect_refused("stride x count = 2^64", h, {"slot_stride", "slot_count", "overflow"});
  h = good_header();
  h.slot_stride = (std::uint64_t{1} << 32) + 256;
  h.slot_count = 0xffffffffu;
  expect_refused("stride x count > 2^64", h, {"slot_stride", "slot_count", "overflow"});
  // header_bytes + stride x count wraps: 4096 + (2^64 - 4096) = 0.
  h = good_header();
  h.slot_count = 1;
  h.slot_stride = ~std::uint64_t{0} - 4095;
  expect_refused("header_bytes + ring wraps", h, {"header_bytes", "overflow"});
}

TEST(ShmReader, RefusesEverySizeFieldOfTheRingHeaderThatDisagreesWithTheSegment) {
  cloudsvc_shm_header h = good_header();
  h.slot_count = 3;  // 4096 + 3 x 4352 = 17152 > 16384
  expect_refused("ring larger than the segment", h, {"17152", "16384"});
  h = good_header();
  h.slot_count = 0;
  expect_refused("no slot", h, {"slot_count 0"});
  h = good_header();
  h.slot_stride = 8;
  expect_refused("stride below the slot header", h, {"slot_stride 8"});
  h = good_header();
  h.slot_stride += 4;
  expect_refused("misaligned stride", h, {"slot_stride", "multiple of 8"});
  h = good_header();
  h.header_bytes = 16;
  expect_refused("slots overlapping the header", h, {"header_bytes 16"});
  h = good_header();
  h.header_bytes = CLOUDSVC_SHM_HEADER_BYTES + 4;
  expect_refused("misaligned slots", h, {"header_bytes", "multiple of 8"});
  h = good_header();
  h.header_bytes = 0xfffffff8u;
  expect_refused("slots beyond the segment", h, {"header_bytes"});
  h = good_header();
  h.max_width = 0;
  expect_refused("no width", h, {"max_width 0"});
  h = good_header();
  h.max_height = 33;  // 16 x 33 x 8 = 4224 > 4096 pixel bytes per slot
  expect_refused("frames larger than a slot", h, {"max_width", "max_height", "4096"});
  h = good_header();
  h.max_width = 0x80000000u;
  h.max_height = 0x80000000u;  // x 8 bytes = 2^65
  expect_refused("max frame overflows", h, {"max_width", "max_height", "overflow"});
  expect_refused("segment smaller than a header", good_header(), {"too small"}, 100);
}

// The slot the ring names as newest, spoiled in one field: both readers refuse it with the
// field's name (C ABI: -3), the C++ reader by an exception instead of a frame.
void expect_bad_slot(const char* what, const std::function<void(TestRing&)>& spoil, const std::string& fragment) {
  SCOPED_TRACE(what);
  TestRing ring("bad-slot", 4, 2);
  spoil(ring);
  ShmFrameReader reader(ring.name());
  ShmFrame f;
  try {
    const bool got = reader.read_latest(0, f);
    ADD_FAILURE() << "read_latest returned " << got << " without an error; frame " << f.info.width << "x"
                  << f.info.height << " with " << f.pixels.size() << " pixel bytes";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(ring.name()), std::string::npos) << e.what();
  }
  cloudsvc_shm_slot header{};
  EXPECT_THROW(reader.read_latest_header(0, header), std::runtime_error);
  char err[256] = "";
  cloudsvc_shm_reader* c = cloudsvc_shm_open(ring.name().c_str(), err, sizeof err);
  ASSERT_NE(c, nullptr) << err;
  std::vector<std::uint8_t> px(1 << 16);
  cloudsvc_shm_slot info{};
  EXPECT_EQ(cloudsvc_shm_read_latest(c, 0, &info, px.data(), px.size()), -3);
  EXPECT_NE(std::string(cloudsvc_shm_last_error(c)).find(fragment), std::string::npos) << cloudsvc_shm_last_error(c);
  cloudsvc_shm_close(c);
}

TEST(ShmReader, RefusesASlotWhoseSizesDisagreeWithTheRing) {
  expect_bad_slot("pixel_bytes beyond the slot", [](TestRing& r) { r.slot(1)->pixel_bytes = std::uint64_t{1} << 40; },
                  "pixel_bytes");
  expect_bad_slot("width above max_width", [](TestRing& r) { r.slot(1)->width = 64; }, "width 64");
  expect_bad_slot("height 0", [](TestRing& r) { r.slot(1)->height = 0; }, "height 0");
  expect_bad_slot("rows shorter than width x 4", [](TestRing& r) {
    r.slot(1)->row_bytes = 8;
    r.slot(1)->pixel_bytes = 16;
  }, "row_bytes 8");
  expect_bad_slot("pixel_bytes != row_bytes x height", [](TestRing& r) { r.slot(1)->pixel_bytes = 16; },
                  "pixel_bytes 16");
  expect_bad_slot("row_bytes x height beyond the slot", [](TestRing& r) {
    r.slot(1)->row_bytes = 0xffffffffu;
    r.slot(1)->pixel_bytes = std::uint64_t{0xffffffffu} * 2;
  }, "pixel_bytes");
  expect_bad_slot("16-bit pixels need 8 bytes each", [](TestRing& r) {
    r.slot(1)->pixel_format = CLOUDSVC_SHM_RGBA16F_LINEAR;  // 4 x 8 = 32 > row_bytes 16
  }, "row_bytes 16");
  expect_bad_slot("unknown pixel format", [](TestRing& r) { r.slot(1)->pixel_format = 7; }, "pixel_format 7");
  expect_bad_slot("latest_slot beyond slot_count", [](TestRing& r) { r.header()->latest_slot = 9; }, "latest_slot 9");
}

TEST(ShmReader, ReadsEveryFrameSizeUpToTheSlotsMaximum) {
  // The largest frame (max_width x max_height at 8 bytes per pixel) fills the slot exactly.
  TestRing ring("full", 4, 2);
  cloudsvc_shm_slot* s = ring.slot(1);
  s->pixel_format = CLOUDSVC_SHM_RGBA16F_LINEAR;
  s->row_bytes = 32;
  s->pixel_bytes = 64;
  ShmFrameReader reader(ring.name());
  ShmFrame f;
  ASSERT_TRUE(reader.read_latest(0, f));
  EXPECT_EQ(f.pixels.size(), 64u);
  // Padded rows (row_bytes > width x bytes per pixel) are allowed when they fit.
  s->pixel_format = CLOUDSVC_SHM_RGBA8_SRGB;
  s->width = 3;
  s->row_bytes = 16;
  s->pixel_bytes = 32;
  s->frame_number = 6;
  ring.header()->latest_frame = 6;
  ASSERT_TRUE(reader.read_latest(5, f));
  EXPECT_EQ(f.info.width, 3u);
  EXPECT_EQ(f.pixels.size(), 32u);
}

// One naming rule for the writer, `cloudsvc serve --shm` and `sim_client watch --shm`.
TEST(ShmName, LettersDigitsDashUnderscoreDotUpTo200) {
  for (const std::string& ok :
       std::vector<std::string>{"cloudsvc-frames", "Cloud_svc-1.frames", "a", "...", std::string(200, 'x')})
    EXPECT_TRUE(valid_shm_name(ok)) << ok;
  for (const std::string& bad :
       std::vector<std::string>{"", ".", "..", "a/b", "/a", "a b", "a\nb", "caf\xc3\xa9", std::string(201, 'x')})
    EXPECT_FALSE(valid_shm_name(bad)) << bad;
}

}  // namespace
}  // namespace cloudsvc
