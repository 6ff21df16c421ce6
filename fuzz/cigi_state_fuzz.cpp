// Fuzz target: a host's datagrams all the way to what the renderer is given
// (docs/CIGI.md): the input is a sequence of datagrams, split before every IG Control header
// (opcode 1, size 24), so the single datagrams of the cigi_datagram seeds and their
// concatenations are both valid inputs. Each is read (read_host_datagram) and applied to one
// IgState; then, as the service does for a frame:
//  - every view's eye and attitude (view_pose) are finite and in range, whatever the
//    ownship's pose and the views' offsets and rotations;
//  - the weather made of the cloud layers (cigi_weather, on a small map) passes the
//    renderer's validate() and its layer coverage is finite and in [0, 1];
// so no NaN or infinity can reach a frame from a host's packets.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "protocol/cigi/cigi_datagram.h"
#include "protocol/cigi/cigi_ig_state.h"
#include "protocol/cigi/cigi_view_pose.h"
#include "protocol/cigi/cigi_weather.h"

using namespace cloudsvc;

namespace {

// Where each datagram starts: 0 and every later IG Control header.
std::vector<std::size_t> datagram_starts(std::span<const std::uint8_t> bytes) {
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 1; i + 1 < bytes.size(); ++i)
    if (bytes[i] == cigi::opcode::kIgControl && bytes[i + 1] == 24) starts.push_back(i);
  return starts;
}

void check_views(const cigi::IgState& s) {
  if (!s.ownship()) return;
  for (const cigi::View& v : s.views()) {
    const cigi::ViewPose p = cigi::view_pose(*s.ownship(), v);
    FUZZ_CHECK(std::isfinite(p.position.lat_deg) && std::abs(p.position.lat_deg) <= 90.0, "a view's latitude");
    FUZZ_CHECK(std::isfinite(p.position.lon_deg) && std::abs(p.position.lon_deg) <= 180.0, "a view's longitude");
    FUZZ_CHECK(std::isfinite(p.position.alt_m), "a view's altitude");
    FUZZ_CHECK(std::isfinite(p.attitude.heading_deg) && std::isfinite(p.attitude.pitch_deg) &&
                   std::isfinite(p.attitude.roll_deg),
               "a view's attitude");
    FUZZ_CHECK(v.frustum.left_deg < v.frustum.right_deg && v.frustum.bottom_deg < v.frustum.top_deg,
               "a view's frustum is not empty");
  }
}

void check_weather(const cigi::IgState& s) {
  const double lat = s.ownship() ? s.ownship()->lat_deg : 0.0, lon = s.ownship() ? s.ownship()->lon_deg : 0.0;
  const cigi::CigiWeather w = cigi::cigi_weather(s, lat, lon, 32, 16);
  FUZZ_CHECK(weather::validate(w.weather).empty(), "the weather of a host's layers is one the renderer takes");
  for (float c : w.map.layer_coverage) FUZZ_CHECK(std::isfinite(c) && c >= 0.0f && c <= 1.0f, "layer coverage in [0, 1]");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  const std::vector<std::size_t> starts = datagram_starts(bytes);
  cigi::IgState state;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const std::size_t end = i + 1 < starts.size() ? starts[i + 1] : size;
    state.apply(cigi::read_host_datagram(bytes.subspan(starts[i], end - starts[i])));
    check_views(state);
  }
  check_weather(state);
  return 0;
}
