// Writes the generated seed corpora of the fuzz targets whose inputs are binary, so that no
// binary seed is committed: `fuzz_make_seeds <dir>` (re)creates <dir>/<target>/ for
//   protocol_decode    one encoded payload per message (seed_messages.h), valid or not;
//   protocol_framing   streams of framed payloads, whole and cut short, behind the two
//                      bytes that choose the chunking and the payload limit;
//   protocol_session   client connections behind the offered-capabilities byte: a full
//                      session, one refused at the handshake, one with a bad frame;
//   protocol_validate, weather_timeline  pseudo-random bytes (for FuzzedDataProvider any
//                      bytes are a valid input; these give it a start beyond the empty one);
//   simclient_map_image  small images (seed_images.h);
//   cigi_datagram      CIGI host datagrams (IG Control with every honoured packet, in
//                      both byte orders, and one cut short) and an IG datagram;
//   cigi_state         sequences of host datagrams with an ownship, views and layers.
// The build runs it into build-san/fuzz/seeds (fuzz/CMakeLists.txt).
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz/seed_images.h"
#include "fuzz/seed_messages.h"
#include "protocol/cigi/cigi_datagram.h"
#include "protocol/codec.h"
#include "protocol/framing.h"

namespace {

using namespace cloudsvc;
using Bytes = std::vector<std::uint8_t>;
namespace fs = std::filesystem;

void write_file(const fs::path& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

fs::path fresh_dir(const fs::path& root, const std::string& target) {
  const fs::path dir = root / target;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void append(Bytes& out, const Bytes& more) { out.insert(out.end(), more.begin(), more.end()); }

Bytes framed(const protocol::Message& m, std::uint64_t seq) { return protocol::frame(protocol::encode(m, seq)); }

void write_decode_seeds(const fs::path& root) {
  const fs::path dir = fresh_dir(root, "protocol_decode");
  std::uint64_t seq = 1;
  for (const auto& [name, m] : fuzz::valid_seed_messages()) write_file(dir / name, protocol::encode(m, seq++));
  for (const auto& [name, m] : fuzz::invalid_seed_messages()) write_file(dir / name, protocol::encode(m, seq++));
}

void write_framing_seeds(const fs::path& root) {
  const fs::path dir = fresh_dir(root, "protocol_framing");
  const auto messages = fuzz::valid_seed_messages();
  // chunking seed, limit selector (< 128: 64 MiB; 128 + k: 16 + 64 k bytes), then frames
  Bytes three = {0x11, 0x00};
  for (std::size_t i = 0; i < 3; ++i) append(three, framed(messages[i].second, i + 1));
  write_file(dir / "three-frames", three);
  Bytes cut = three;
  cut.resize(cut.size() - 5);
  write_file(dir / "cut-short", cut);
  Bytes small_limit = {0x5a, 128 + 2};  // 144-byte limit: the tile's frame is over it
  append(small_limit, framed(messages[3].second, 1));
  append(small_limit, framed(messages[6].second, 2));
  write_file(dir / "over-limit", small_limit);
  Bytes bad_magic = {0x03, 0x00};
  append(bad_magic, framed(messages[4].second, 1));
  append(bad_magic, Bytes{'C', 'S', 'V', '2', 4, 0, 0, 0, 1, 2, 3, 4});
  write_file(dir / "bad-magic", bad_magic);
}

void write_session_seeds(const fs::path& root) {
  const fs::path dir = fresh_dir(root, "protocol_session");
  const auto valid = fuzz::valid_seed_messages();
  const auto invalid = fuzz::invalid_seed_messages();
  const std::uint8_t all = static_cast<std::uint8_t>(protocol::capability::kAll);
  Bytes session = {all};
  std::uint64_t seq = 1;
  append(session, framed(valid[0].second, seq++));  // Hello
  for (const char* name : {"set-view", "pose", "set-time", "weather-layers", "weather-map-tile",
                           "render-request", "stats-request", "welcome"}) {
    for (const auto& [n, m] : valid)
      if (n == name) append(session, framed(m, seq++));
  }
  for (const auto& [n, m] : invalid) append(session, framed(m, seq++));
  write_file(dir / "full-session", session);
  Bytes no_caps = session;
  no_caps[0] = 0;
  write_file(dir / "no-capabilities", no_caps);
  Bytes pose_first = {all};
  append(pose_first, framed(valid[3].second, 1));
  write_file(dir / "pose-before-hello", pose_first);
  Bytes future = {all};
  append(future, framed(invalid.back().second, 1));  // Hello of major 2
  write_file(dir / "version-mismatch", future);
  Bytes bad_frame = {all};
  append(bad_frame, framed(valid[0].second, 1));
  append(bad_frame, Bytes{'C', 'S', 'V', '1', 0, 0, 0, 0});  // zero length
  write_file(dir / "zero-length-frame", bad_frame);
}

// Deterministic bytes (xorshift32) for the FuzzedDataProvider targets.
void write_random_seeds(const fs::path& root, const std::string& target, std::uint32_t state) {
  const fs::path dir = fresh_dir(root, target);
  for (const std::size_t size : {32, 64, 128, 256, 512, 1024}) {
    Bytes bytes(size);
    for (std::uint8_t& b : bytes) {
      state ^= state << 13;
      state ^= state >> 17;
      state ^= state << 5;
      b = static_cast<std::uint8_t>(state >> 24);
    }
    write_file(dir / ("random-" + std::to_string(size)), bytes);
  }
}

}  // namespace

void write_cigi_seeds(const fs::path& root) {
  using namespace cloudsvc::cigi;
  const fs::path dir = fresh_dir(root, "cigi_datagram");
  for (ByteOrder order : {ByteOrder::Big, ByteOrder::Little}) {
    const std::string suffix = order == ByteOrder::Big ? "-big" : "-little";
    DatagramWriter w(order);
    w.add(IgControl{});
    w.add(EntityControl{});
    w.add(ViewControl{});
    ViewDefinition v;
    v.enable = 0x3f;
    v.near_m = 1.0f, v.far_m = 1.0e5f, v.left_deg = -30.0f, v.right_deg = 30.0f, v.top_deg = 20.0f, v.bottom_deg = -20.0f;
    w.add(v);
    w.add(CelestialSphereControl{});
    w.add(AtmosphereControl{});
    w.add(EnvironmentalRegionControl{});
    w.add(WeatherControl{});
    write_file(dir / ("host" + suffix), w.bytes());
    Bytes cut = w.bytes();
    cut.resize(cut.size() - 13);
    write_file(dir / ("host-cut" + suffix), cut);
    DatagramWriter ig(order);
    ig.add(StartOfFrame{});
    ig.add(IgMessage{1, "View Definition at byte 24: far_m 0 out of range"});
    write_file(dir / ("ig" + suffix), ig.bytes());
  }
}

// cigi_state: sequences of host datagrams (one after another, as the IG receives them)
// that give an ownship, three views, global layers and a region with its own layers.
void write_cigi_state_seeds(const fs::path& root) {
  using namespace cloudsvc::cigi;
  const fs::path dir = fresh_dir(root, "cigi_state");
  for (ByteOrder order : {ByteOrder::Big, ByteOrder::Little}) {
    const std::string suffix = order == ByteOrder::Big ? "-big" : "-little";
    Bytes sequence;
    for (std::uint32_t frame = 1; frame <= 2; ++frame) {
      DatagramWriter w(order);
      IgControl c;
      c.host_frame = frame;
      w.add(c);
      EntityControl e;
      e.lat_deg = 47.45 + 0.01 * frame, e.lon_deg = 8.56, e.alt_m = 3000.0, e.yaw_deg = 90.0f, e.pitch_deg = -5.0f;
      w.add(e);
      for (std::uint16_t id = 0; id < 3; ++id) {
        ViewControl vc;
        vc.view_id = id, vc.enable = view_enable::kYaw | view_enable::kY, vc.yaw_deg = 60.0f * (id - 1), vc.y_m = id;
        w.add(vc);
      }
      EnvironmentalRegionControl r;
      r.region_id = 7, r.lat_deg = 47.5, r.lon_deg = 8.6, r.size_x_m = 20000.0f, r.size_y_m = 10000.0f;
      r.corner_radius_m = 2000.0f, r.rotation_deg = 30.0f, r.transition_perimeter_m = 5000.0f;
      w.add(r);
      WeatherControl global;
      w.add(global);
      WeatherControl regional = global;
      regional.scope = WeatherScope::Regional, regional.entity_or_region_id = 7, regional.layer_id = 2;
      regional.base_elevation_m = 1500.0f, regional.coverage_pct = 90.0f;
      w.add(regional);
      sequence.insert(sequence.end(), w.bytes().begin(), w.bytes().end());
    }
    write_file(dir / ("sequence" + suffix), sequence);
  }
}

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <seed-dir>\n", argv[0]);
    return 2;
  }
  try {
    const fs::path root = argv[1];
    write_decode_seeds(root);
    write_framing_seeds(root);
    write_session_seeds(root);
    write_cigi_seeds(root);
    write_cigi_state_seeds(root);
    write_random_seeds(root, "protocol_validate", 0x2545f491u);
    write_random_seeds(root, "weather_timeline", 0x9e3779b9u);
    fuzz::write_seed_images(fresh_dir(root, "simclient_map_image"));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_seeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
