// Fuzz target: protocol::validate() (protocol/validate.h), protocol::encode() and the
// service's per-message rule check_client_message() (protocol/handshake.h) on messages
// built field by field from the input (FuzzedDataProvider, fuzz/fuzzed_values.h), so that
// every field takes boundary, non-finite and ordinary values without going through the
// FlatBuffers layout (protocol_decode covers that).
// Invariants checked besides the sanitizers':
//  - validate() and the wire agree: encode() then decode() accepts exactly the messages
//    validate() accepts, gives them back unchanged, and refuses the others with
//    InvalidField;
//  - a refusal text names the problem on one line and fits an Error message (the service
//    sends it back to the client as Error{InvalidField});
//  - check_client_message() refuses service-only messages and Hello with
//    UnexpectedMessage, and client messages exactly when they need a capability that was
//    not offered.
#include <cstddef>
#include <cstdint>
#include <variant>

#include "fuzz/fuzz_check.h"
#include "fuzz/fuzzed_values.h"
#include "fuzz/sendable.h"
#include "protocol/codec.h"
#include "protocol/handshake.h"
#include "protocol/limits.h"
#include "protocol/validate.h"

namespace {

using namespace cloudsvc;
using namespace cloudsvc::protocol;
using fuzz::any_double;
using fuzz::any_string;

Pose make_pose(FuzzedDataProvider& in) {
  Pose p;
  p.sim_time_s = any_double(in);
  if (in.ConsumeBool()) p.utc_unix_s = any_double(in);
  p.lat_deg = any_double(in);
  p.lon_deg = any_double(in);
  p.alt_m = any_double(in);
  p.heading_deg = any_double(in);
  p.pitch_deg = any_double(in);
  p.roll_deg = any_double(in);
  if (in.ConsumeBool()) p.velocity_enu = VelocityEnu{any_double(in), any_double(in), any_double(in)};
  p.flags = in.ConsumeIntegral<std::uint8_t>();
  return p;
}

CloudLayer make_layer(FuzzedDataProvider& in) {
  CloudLayer l;
  l.type = in.ConsumeIntegralInRange<std::uint8_t>(0, 12);
  l.base_m = any_double(in);
  l.top_m = in.ConsumeBool() ? l.base_m + any_double(in) : any_double(in);
  l.coverage = any_double(in);
  l.density_scale = any_double(in);
  l.droplet_diameter_um = any_double(in);
  l.wind_east_mps = any_double(in);
  l.wind_north_mps = any_double(in);
  return l;
}

// A tile whose data has the size its header asks for (when that is small) or any size.
WeatherMapTile make_tile(FuzzedDataProvider& in) {
  WeatherMapTile t;
  t.lat_min_deg = any_double(in);
  t.lat_max_deg = in.ConsumeBool() ? t.lat_min_deg + any_double(in) : any_double(in);
  t.lon_min_deg = any_double(in);
  t.lon_max_deg = in.ConsumeBool() ? t.lon_min_deg + any_double(in) : any_double(in);
  const bool small = in.ConsumeBool();
  t.width = small ? in.ConsumeIntegralInRange<std::uint32_t>(0, 9) : in.ConsumeIntegral<std::uint32_t>();
  t.height = small ? in.ConsumeIntegralInRange<std::uint32_t>(0, 9) : in.ConsumeIntegral<std::uint32_t>();
  t.channels = in.ConsumeIntegral<std::uint8_t>();
  t.valid_at_utc_s = in.ConsumeBool() ? fuzz::utc_time(in) : any_double(in);
  const std::uint64_t wanted = std::uint64_t{t.width} * t.height * t.channel_count();
  const std::size_t n = in.ConsumeBool() && wanted <= 1024 ? wanted : in.ConsumeIntegralInRange<std::size_t>(0, 64);
  t.data.resize(n);
  for (float& v : t.data) v = fuzz::any_float(in);
  return t;
}

Message make_message(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegralInRange<int>(0, std::variant_size_v<Message> - 1)) {
    case 0:
      return Hello{in.ConsumeIntegral<std::uint16_t>(), in.ConsumeIntegral<std::uint16_t>(),
                   any_string(in, kMaxNameBytes + 8), in.ConsumeIntegral<std::uint32_t>()};
    case 1: {
      Welcome w;
      w.major = in.ConsumeIntegral<std::uint16_t>();
      w.minor = in.ConsumeIntegral<std::uint16_t>();
      w.service_version = any_string(in, kMaxVersionBytes + 8);
      w.capabilities = in.ConsumeIntegral<std::uint32_t>();
      w.limits = Limits{in.ConsumeIntegral<std::uint32_t>(), in.ConsumeIntegral<std::uint32_t>(),
                        in.ConsumeIntegral<std::uint8_t>(), in.ConsumeIntegral<std::uint32_t>()};
      return w;
    }
    case 2: {
      SetView v;
      v.width = in.ConsumeIntegralInRange<std::uint32_t>(0, kMaxImageSize + 1);
      v.height = in.ConsumeIntegralInRange<std::uint32_t>(0, kMaxImageSize + 1);
      v.hfov_deg = any_double(in);
      v.sinks = in.ConsumeIntegral<std::uint8_t>();
      v.shm_format = static_cast<ShmPixelFormat>(in.ConsumeIntegralInRange<std::uint8_t>(0, 3));
      v.file_dir = any_string(in, 64);
      v.file_format = static_cast<FileFormat>(in.ConsumeIntegralInRange<std::uint8_t>(0, 3));
      v.quality_preset = any_string(in, kMaxPresetBytes + 8);
      return v;
    }
    case 3:
      return make_pose(in);
    case 4:
      return SetTime{any_double(in)};
    case 5: {
      WeatherLayers w;
      w.layers.resize(in.ConsumeIntegralInRange<std::size_t>(0, kMaxLayers + 1));
      for (CloudLayer& l : w.layers) l = make_layer(in);
      w.map_seed = in.ConsumeIntegral<std::uint32_t>();
      return w;
    }
    case 6:
      return make_tile(in);
    case 7:
      return RenderRequest{in.ConsumeIntegralInRange<std::uint64_t>(0, 3)};
    case 8: {
      FrameReady f;
      f.frame_number = in.ConsumeIntegral<std::uint64_t>();
      f.request_id = in.ConsumeIntegral<std::uint64_t>();
      f.pose = make_pose(in);
      f.sim_time_s = any_double(in);
      if (in.ConsumeBool()) f.shm_slot = in.ConsumeIntegral<std::uint32_t>();
      f.width = in.ConsumeIntegralInRange<std::uint32_t>(0, kMaxImageSize + 1);
      f.height = in.ConsumeIntegralInRange<std::uint32_t>(0, kMaxImageSize + 1);
      f.render_ms = any_double(in);
      f.latency_ms = any_double(in);
      if (in.ConsumeBool()) f.file_path = any_string(in, 64);
      return f;
    }
    case 9:
      return Error{static_cast<ErrorCode>(in.ConsumeIntegral<std::uint16_t>()),
                   any_string(in, kMaxErrorTextBytes + 8), in.ConsumeIntegral<std::uint64_t>()};
    case 10:
      return StatsRequest{};
    default: {
      Stats s;
      s.frames_rendered = in.ConsumeIntegral<std::uint64_t>();
      s.fps = any_double(in);
      s.poses_received = in.ConsumeIntegral<std::uint64_t>();
      s.poses_dropped = in.ConsumeIntegral<std::uint64_t>();
      s.clients = in.ConsumeIntegral<std::uint32_t>();
      s.frame_in_progress_ms = any_double(in);
      return s;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const Message m = make_message(in);
  const std::uint64_t seq = in.ConsumeIntegralInRange<std::uint64_t>(1, UINT64_MAX);
  const std::uint32_t offered = in.ConsumeIntegral<std::uint32_t>();

  const auto problem = validate(m);
  if (problem) {
    FUZZ_CHECK(!problem->empty(), "validate() refuses without saying why");
    fuzz::check_sendable(Error{ErrorCode::InvalidField, *problem, seq}, 1,
                         "the service's Error{InvalidField} for an invalid message");
  }
  const DecodeResult back = decode(encode(m, seq));
  if (problem) {
    FUZZ_CHECK(!back.ok() && back.error == ErrorCode::InvalidField,
               "an invalid message is not refused with InvalidField after encode()");
  } else {
    FUZZ_CHECK(back.ok() && back.seq == seq && *back.message == m,
               "a valid message does not survive encode() -> decode()");
  }

  const auto refusal = check_client_message(m, seq, offered);
  if (sender_of(m) == Sender::Service || std::holds_alternative<Hello>(m)) {
    FUZZ_CHECK(refusal && refusal->code == ErrorCode::UnexpectedMessage,
               "a message clients may not send was let through");
  } else {
    FUZZ_CHECK(!check_client_message(m, seq, capability::kAll),
               "a client message was refused although every capability is offered");
    if (refusal) FUZZ_CHECK(refusal->code == ErrorCode::CapabilityMissing, "a refusal other than CapabilityMissing");
  }
  if (refusal) {
    FUZZ_CHECK(refusal->answers_seq == seq, "the Error does not answer the message's seq");
    fuzz::check_sendable(*refusal, 1, "the service's Error for a message it does not take");
  }
  return 0;
}
