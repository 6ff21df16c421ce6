// `cloudsvc serve --cigi` driven by a CIGI 3.3 host (docs/CIGI.md): `sim_client cigi` flies a
// log through the IG in both byte orders, and each host frame gets one Start of Frame and one
// image per view (files DIR/view<ID>/, rings NAME-view<ID>); a view turned 60° right of the
// nose shows what a single view with the aircraft turned 60° shows; bad datagrams are answered
// with IG Messages while the IG goes on, and so is a visibility below the drawn range; an
// asynchronous IG renders at its own rate.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>
#include <optional>

#include "cloudsvc_run.h"
#include "protocol/cigi/cigi_datagram.h"
#include "service_test_support.h"
#include "sim_client/cigi_host_link.h"

namespace cloudsvc::test {
namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;

// The IG's address from the ready file (its line udp:HOST:PORT).
std::string cigi_address(const ServiceProcess& svc) {
  std::ifstream f(svc.ready_path());
  for (std::string line; std::getline(f, line);)
    if (line.rfind("udp:", 0) == 0) return line;
  return "";
}

cli::UdpEndpoint cigi_endpoint(const ServiceProcess& svc) {
  cli::UdpEndpoint ig;
  EXPECT_FALSE(cli::udp_endpoint_problem(cigi_address(svc), cli::PortUse::Connect, ig));
  return ig;
}

// The ownship (entity 0) over Zurich at 3000 m, level, heading north.
cigi::EntityControl ownship_over_zurich() {
  cigi::EntityControl ownship;
  ownship.lat_deg = 47.45;
  ownship.lon_deg = 8.56;
  ownship.alt_m = 3000.0;
  return ownship;
}

// A short log above scattered cumulus: 3000 m, level (a view yawed in the body axes of a
// pitched aircraft would not be a level view turned).
fs::path write_log(const fs::path& dir, double heading_deg) {
  const fs::path p = dir / ("flight_" + std::to_string(static_cast<int>(heading_deg)) + ".csv");
  std::ofstream f(p);
  f << "time,lat,lon,alt,heading,pitch,roll\n";
  for (int s = 0; s < 3; ++s)
    f << "2026-06-21T10:00:0" << s << "Z,47.45," << 8.56 + 0.0008 * s << ",3000," << heading_deg << ",0,0\n";
  return p;
}

std::vector<float> read_png(const fs::path& p) {
  auto in = OIIO::ImageInput::open(p.string());
  if (!in) return {};
  const OIIO::ImageSpec& s = in->spec();
  std::vector<float> px(static_cast<std::size_t>(s.width) * s.height * s.nchannels);
  in->read_image(0, 0, 0, s.nchannels, OIIO::TypeDesc::FLOAT, px.data());
  return px;
}

double mean_abs_difference(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size() || a.empty()) return 1e9;
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d += std::abs(a[i] - b[i]);
  return d / static_cast<double>(a.size());
}

fs::path frame_file(const ServiceProcess& svc, int view, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06d.png", frame);
  return svc.out_dir() / ("view" + std::to_string(view)) / name;
}

TEST(CigiService, ASynchronousHostGetsAFrameAndAStartOfFramePerHostFrameInEitherByteOrder) {
  for (const std::string order : {"big", "little"}) {
    ServiceProcess svc("cigi_" + order, {"--cigi", "udp:0", "--exit-after-frames", "3"}, ServiceProcess::Tcp::No,
                       ServiceProcess::OutDir::Yes);
    ASSERT_TRUE(svc.running()) << read_text_file(svc.log_path());
    const std::string ig = cigi_address(svc);
    ASSERT_FALSE(ig.empty()) << read_text_file(svc.ready_path());
    const RunResult r = run_sim_client({"cigi", write_log(svc.dir(), 0.0).string(), "--ig", ig, "--views", "3", "--size",
                                        "64x36", "--byte-order", order, "--max-frames", "3"},
                                       svc.dir());
    ASSERT_EQ(r.exit_code, 0) << r.err << read_text_file(svc.log_path());
    EXPECT_NE(r.out.find("3 host frames sent (" + order + "-endian, synchronous), 3 Start of Frame received (IG "
                         "frames 1-3), 0 sent again, 0 IG Messages"),
              std::string::npos)
        << r.out << r.err;
    ASSERT_EQ(svc.wait_exit(120s), 0) << read_text_file(svc.log_path());
    for (int view = 0; view < 3; ++view)
      for (int frame = 1; frame <= 3; ++frame) EXPECT_TRUE(fs::exists(frame_file(svc, view, frame))) << view << " " << frame;
    EXPECT_FALSE(fs::exists(frame_file(svc, 3, 1))) << "only the host's three views";
  }
}

// Each view is a channel with its own orientation: the right view of a north-bound cockpit
// (view 2, 60° right of the nose) is the forward view of an aircraft heading 060°.
TEST(CigiService, AViewTurnedRightOfTheNoseSeesWhatTheTurnedAircraftSees) {
  std::vector<std::vector<float>> three(3);
  std::vector<float> turned;
  {
    ServiceProcess svc("cigi_three", {"--cigi", "udp:0", "--exit-after-frames", "1"}, ServiceProcess::Tcp::No,
                       ServiceProcess::OutDir::Yes);
    ASSERT_TRUE(svc.running());
    const RunResult r = run_sim_client({"cigi", write_log(svc.dir(), 0.0).string(), "--ig", cigi_address(svc), "--views",
                                        "3", "--size", "64x36", "--max-frames", "1"},
                                       svc.dir());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_EQ(svc.wait_exit(120s), 0);
    for (int v = 0; v < 3; ++v) three[v] = read_png(frame_file(svc, v, 1));
  }
  {
    ServiceProcess svc("cigi_turned", {"--cigi", "udp:0", "--exit-after-frames", "1"}, ServiceProcess::Tcp::No,
                       ServiceProcess::OutDir::Yes);
    ASSERT_TRUE(svc.running());
    const RunResult r = run_sim_client({"cigi", write_log(svc.dir(), 60.0).string(), "--ig", cigi_address(svc), "--size",
                                        "64x36", "--max-frames", "1"},
                                       svc.dir());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_EQ(svc.wait_exit(120s), 0);
    turned = read_png(frame_file(svc, 0, 1));
  }
  const double same = mean_abs_difference(three[2], turned);
  const double left_vs_right = mean_abs_difference(three[0], three[2]);
  std::printf("view 2 vs the turned aircraft: %.4f; view 0 vs view 2: %.4f (8-bit sRGB, 0..1)\n", same, left_vs_right);
  EXPECT_LT(same, 0.01);
  EXPECT_GT(left_vs_right, std::max(0.01, 5.0 * same)) << "the comparison tells the views apart";
}

// --cigi-view-quality: a view drawn at another preset differs from its default image while
// the other views, at the default, are the same images as in a run without the flag.
TEST(CigiService, AViewGivenItsOwnQualityIsDrawnWithIt) {
  std::vector<std::vector<float>> plain(3), side(3);
  for (const bool cheap : {false, true}) {
    std::vector<std::string> args = {"--cigi", "udp:0", "--exit-after-frames", "1"};
    if (cheap) {
      args.emplace_back("--cigi-view-quality");
      args.emplace_back("2=low");
    }
    ServiceProcess svc(cheap ? "cigi_view_quality" : "cigi_all_default", args, ServiceProcess::Tcp::No,
                       ServiceProcess::OutDir::Yes);
    ASSERT_TRUE(svc.running()) << read_text_file(svc.log_path());
    const RunResult r = run_sim_client({"cigi", write_log(svc.dir(), 0.0).string(), "--ig", cigi_address(svc), "--views",
                                        "3", "--size", "64x36", "--max-frames", "1"},
                                       svc.dir());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_EQ(svc.wait_exit(120s), 0);
    for (int v = 0; v < 3; ++v) (cheap ? side : plain)[v] = read_png(frame_file(svc, v, 1));
  }
  const double nose = mean_abs_difference(plain[0], side[0]), right = mean_abs_difference(plain[2], side[2]);
  std::printf("default vs --cigi-view-quality 2=low: view 0 %.5f, view 2 %.5f (8-bit sRGB, 0..1)\n", nose, right);
  EXPECT_LT(nose, 0.0005) << "view 0 keeps the default";
  EXPECT_GT(right, std::max(0.001, 5.0 * nose)) << "view 2 is drawn at half the cloud resolution";
}

// Reads the IG's datagrams until one carries an IG Message containing `needle`.
bool message_arrives(sim::CigiHostLink& link, const std::string& needle, std::string& seen) {
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (auto d = link.receive(deadline)) {
    if (!d->usable) continue;
    for (const cigi::IgMessage& m : d->messages) {
      seen += m.text + "\n";
      if (m.text.find(needle) != std::string::npos) return true;
    }
  }
  return false;
}

TEST(CigiService, BadDatagramsAreAnsweredWithIgMessagesAndTheIgGoesOn) {
  ServiceProcess svc("cigi_bad", {"--cigi", "udp:0"}, ServiceProcess::Tcp::No, ServiceProcess::OutDir::Yes);
  ASSERT_TRUE(svc.running());
  sim::CigiHostLink link(cigi_endpoint(svc));
  std::string seen;

  link.send({1, 2, 3, 4, 5});  // shorter than an IG Control
  EXPECT_TRUE(message_arrives(link, "IG Control", seen)) << seen;

  cigi::IgControl control;
  control.host_frame = 1;
  cigi::EntityControl ownship = ownship_over_zurich();
  ownship.pitch_deg = -15.0f;
  cigi::EntityControl bad = ownship;
  bad.lat_deg = std::nan("");
  for (cigi::ByteOrder order : {cigi::ByteOrder::Big, cigi::ByteOrder::Little}) {
    cigi::DatagramWriter w(order);
    w.add(control);
    w.add(ownship);
    w.add(bad);  // refused whole: the ownship stays where the packet before put it
    std::vector<std::uint8_t> bytes = w.bytes();
    const std::vector<std::uint8_t> unknown = {77, 8, 0, 0, 0, 0, 0, 0};  // skipped by its size
    bytes.insert(bytes.end(), unknown.begin(), unknown.end());
    link.send(bytes);
    EXPECT_TRUE(message_arrives(link, "lat_deg", seen)) << seen;
    ++control.host_frame;
  }
  control.major_version = 2;  // a wrong major version: nothing of it is used
  {
    cigi::DatagramWriter w;
    w.add(control);
    link.send(w.bytes());
    EXPECT_TRUE(message_arrives(link, "version", seen)) << seen;
  }
  // The IG still draws: the two good host frames were rendered from the ownship's pose.
  EXPECT_TRUE(svc.running());
  EXPECT_TRUE(fs::exists(frame_file(svc, 0, 1))) << read_text_file(svc.log_path());
  EXPECT_EQ(svc.stop(), 0);
  EXPECT_NE(read_text_file(svc.log_path()).find("cloudsvc serve: CIGI: "), std::string::npos);
}

// A mirrored view is the same view flipped: three views at one pose, unmirrored, mirrored
// horizontally and vertically, drawn in one IG frame (each on its own channel, its first
// frame, so the same render).
TEST(CigiService, AMirroredViewIsTheViewFlipped) {
  ServiceProcess svc("cigi_mirror", {"--cigi", "udp:0", "--exit-after-frames", "1"}, ServiceProcess::Tcp::No,
                     ServiceProcess::OutDir::Yes);
  ASSERT_TRUE(svc.running());
  sim::CigiHostLink link(cigi_endpoint(svc));
  cigi::IgControl control;
  control.host_frame = 1;
  cigi::EntityControl ownship = ownship_over_zurich();
  ownship.pitch_deg = -20.0f;  // ground, clouds and sky: no symmetry either way
  ownship.yaw_deg = 200.0f;
  cigi::DatagramWriter w;
  w.add(control);
  w.add(ownship);
  for (std::uint8_t id = 0; id < 3; ++id) {
    cigi::ViewDefinition d;
    d.view_id = id;
    d.mirror = id;  // 0 none, 1 horizontal, 2 vertical
    d.enable = cigi::definition_enable::kLeft | cigi::definition_enable::kRight | cigi::definition_enable::kTop |
               cigi::definition_enable::kBottom;
    d.left_deg = -35.0f;
    d.right_deg = 25.0f;  // off-axis: the flip is of the image, not of the frustum
    d.top_deg = 15.0f;
    d.bottom_deg = -20.0f;
    w.add(d);
  }
  link.send(w.bytes());
  ASSERT_EQ(svc.wait_exit(120s), 0) << read_text_file(svc.log_path());
  const std::vector<float> plain = read_png(frame_file(svc, 0, 1)), lr = read_png(frame_file(svc, 1, 1)),
                           tb = read_png(frame_file(svc, 2, 1));
  ASSERT_FALSE(plain.empty());
  const int width = 64, height = 36, channels = static_cast<int>(plain.size() / (width * height));
  ASSERT_EQ(plain.size(), static_cast<std::size_t>(width * height * channels));
  std::vector<float> plain_lr(plain.size()), plain_tb(plain.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < channels; ++c) {
        const float v = plain[(static_cast<std::size_t>(y) * width + x) * channels + c];
        plain_lr[(static_cast<std::size_t>(y) * width + (width - 1 - x)) * channels + c] = v;
        plain_tb[(static_cast<std::size_t>(height - 1 - y) * width + x) * channels + c] = v;
      }
  EXPECT_LT(mean_abs_difference(lr, plain_lr), 1e-3);
  EXPECT_LT(mean_abs_difference(tb, plain_tb), 1e-3);
  EXPECT_GT(mean_abs_difference(lr, plain), 0.02) << "the view is not symmetric left to right: the test tells";
  EXPECT_GT(mean_abs_difference(tb, plain), 0.02) << "nor top to bottom";
}

// An Atmosphere Control's visibility below the drawn range (fog, 300 m) is not refused: it is
// drawn as 1000 m and an IG Message says so; the IG draws with it, then with a visibility in
// the range (no message, nothing refused).
TEST(CigiService, AVisibilityBelowTheDrawnRangeIsDrawnAtItsEndAndAnIgMessageSaysSo) {
  ServiceProcess svc("cigi_visibility", {"--cigi", "udp:0"}, ServiceProcess::Tcp::No, ServiceProcess::OutDir::Yes);
  ASSERT_TRUE(svc.running());
  sim::CigiHostLink link(cigi_endpoint(svc));
  cigi::EntityControl ownship = ownship_over_zurich();
  std::string seen;  // the IG Messages, one a line
  // Sends host frame n (with an Atmosphere Control of that visibility, m, if any) and reads
  // until its Start of Frame, which carries the messages of its IG frame and follows the
  // drawing of the frame before.
  const auto host_frame = [&](std::uint32_t n, std::optional<float> visibility_m) {
    cigi::IgControl control;
    control.host_frame = n;
    cigi::DatagramWriter w;
    w.add(control);
    w.add(ownship);
    if (visibility_m) {
      cigi::AtmosphereControl atmosphere;
      atmosphere.visibility_m = *visibility_m;
      w.add(atmosphere);
    }
    link.send(w.bytes());
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    for (std::uint32_t last = 0; last < n;) {
      const auto d = link.receive(deadline);
      if (!d) return false;
      if (!d->usable) continue;
      last = d->start_of_frame.last_host_frame;
      for (const cigi::IgMessage& m : d->messages) seen += m.text + "\n";
    }
    return true;
  };
  ASSERT_TRUE(host_frame(1, 300.0f)) << seen;
  EXPECT_EQ(seen, "Atmosphere Control: visibility 300 m drawn as 1000 m (fog is not drawn)\n");
  ASSERT_TRUE(host_frame(2, 20000.0f)) << seen;
  ASSERT_TRUE(host_frame(3, std::nullopt)) << seen;
  EXPECT_EQ(seen, "Atmosphere Control: visibility 300 m drawn as 1000 m (fog is not drawn)\n") << "nothing else";
  EXPECT_TRUE(fs::exists(frame_file(svc, 0, 1))) << read_text_file(svc.log_path());
  EXPECT_TRUE(fs::exists(frame_file(svc, 0, 2))) << read_text_file(svc.log_path());
  EXPECT_EQ(svc.stop(), 0);
}

// A host that floods a synchronous IG (it should wait for each Start of Frame) neither
// stalls it nor grows its queue: beyond 64 waiting host frames the oldest are applied
// without a frame of their own, and an IG Message says so.
TEST(CigiService, AFloodOfHostFramesIsAppliedWithoutStallingTheIg) {
  ServiceProcess svc("cigi_flood", {"--cigi", "udp:0"}, ServiceProcess::Tcp::No, ServiceProcess::OutDir::Yes);
  ASSERT_TRUE(svc.running());
  sim::CigiHostLink link(cigi_endpoint(svc));
  cigi::EntityControl ownship = ownship_over_zurich();
  constexpr std::uint32_t kFrames = 200;  // within a socket's receive buffer
  for (std::uint32_t n = 1; n <= kFrames; ++n) {
    cigi::IgControl control;
    control.host_frame = n;
    cigi::DatagramWriter w;
    w.add(control);
    w.add(ownship);
    link.send(w.bytes());
  }
  std::string seen;
  EXPECT_TRUE(message_arrives(link, "applied without a frame of its own", seen)) << seen;
  // The IG goes on: a Start of Frame for the newest host frame that arrived comes, well
  // before the 200 frames could have been drawn one by one.
  std::uint32_t last_host_frame = 0;
  const auto deadline = std::chrono::steady_clock::now() + 120s;
  while (auto d = link.receive(deadline)) {
    if (d->usable) last_host_frame = std::max(last_host_frame, d->start_of_frame.last_host_frame);
    if (last_host_frame >= kFrames - 64) break;
  }
  EXPECT_GE(last_host_frame, kFrames - 64);
  EXPECT_EQ(svc.stop(), 0);
}

TEST(CigiService, AnAsynchronousIgRendersAtItsOwnRateFromTheNewestState) {
  ServiceProcess svc("cigi_async", {"--cigi", "udp:0", "--cigi-mode", "async", "--cigi-rate", "20"},
                     ServiceProcess::Tcp::No, ServiceProcess::OutDir::Yes);
  ASSERT_TRUE(svc.running());
  const RunResult r = run_sim_client({"cigi", write_log(svc.dir(), 0.0).string(), "--ig", cigi_address(svc), "--mode",
                                      "async", "--fps", "4", "--max-frames", "6", "--size", "64x36"},
                                     svc.dir());
  ASSERT_EQ(r.exit_code, 0) << r.err << read_text_file(svc.log_path());
  EXPECT_NE(r.out.find("6 host frames sent"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("asynchronous"), std::string::npos) << r.out;
  // Frames are not tied to host frames: the IG keeps drawing with no new host frame.
  const auto files = [&] {
    std::size_t n = 0;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(svc.out_dir() / "view0", ec)) n += e.is_regular_file();
    return n;
  };
  const auto deadline = std::chrono::steady_clock::now() + 120s;
  const auto wait_for_more_than = [&](std::size_t n) {
    while (files() <= n && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(50ms);  // polling a directory; the deadline bounds it
    return files();
  };
  const std::size_t before = wait_for_more_than(0);
  ASSERT_GE(before, 1u);
  EXPECT_GT(wait_for_more_than(before), before);
  EXPECT_EQ(svc.stop(), 0);
}

TEST(CigiService, EachViewHasItsOwnSharedMemoryRing) {
  ServiceProcess svc("cigi_shm", {"--cigi", "udp:0"});
  ASSERT_TRUE(svc.running());
  const RunResult r = run_sim_client({"cigi", write_log(svc.dir(), 0.0).string(), "--ig", cigi_address(svc), "--views",
                                      "2", "--size", "64x36", "--max-frames", "3"},
                                     svc.dir());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The Start of Frame of host frame 3 came after frames 1 and 2 were published.
  EXPECT_TRUE(fs::exists("/dev/shm/" + svc.shm_name() + "-view0"));
  EXPECT_TRUE(fs::exists("/dev/shm/" + svc.shm_name() + "-view1"));
  EXPECT_FALSE(fs::exists("/dev/shm/" + svc.shm_name() + "-view2"));
  EXPECT_EQ(svc.stop(), 0);
  EXPECT_FALSE(fs::exists("/dev/shm/" + svc.shm_name() + "-view0")) << "removed at the stop";
}

}  // namespace
}  // namespace cloudsvc::test
