// decode(): untrusted payload bytes -> verified FlatBuffers Envelope -> validated Message.
#include <cstring>

#include "protocol/codec.h"
#include "protocol/limits.h"
#include "protocol/validate.h"
#include "protocol/wire.h"

namespace cloudsvc::protocol {
namespace {

namespace fb = flatbuffers;

// Smallest possible Envelope: root offset (4) + file identifier (4) + vtable (4) + table (4).
constexpr std::size_t kMinPayloadBytes = 16;

// Verifier limits. The deepest legal nesting is Envelope -> WeatherLayers -> [CloudLayer]
// -> CloudLayer; the table count only bounds the verifier's work on hostile input (a legal
// message has at most 7 tables; extra layers are reported by validate(), not here).
constexpr fb::uoffset_t kMaxDepth = 16;
constexpr fb::uoffset_t kMaxTables = 4096;

std::string str(const fb::String* s) { return s ? s->str() : std::string(); }

Pose get_pose(const wire::Pose& p) {
  Pose out;
  out.sim_time_s = p.sim_time_s();
  if (const auto utc = p.utc_unix_s()) out.utc_unix_s = *utc;
  out.lat_deg = p.lat_deg();
  out.lon_deg = p.lon_deg();
  out.alt_m = p.alt_m();
  out.heading_deg = p.heading_deg();
  out.pitch_deg = p.pitch_deg();
  out.roll_deg = p.roll_deg();
  if (const wire::Vec3* v = p.velocity_enu()) {
    out.velocity_enu = VelocityEnu{v->east(), v->north(), v->up()};
  }
  out.flags = p.flags();
  return out;
}

Hello get(const wire::Hello& m) {
  return Hello{m.major(), m.minor(), str(m.client_name()), m.capabilities()};
}

Welcome get(const wire::Welcome& m) {
  Welcome out{m.major(), m.minor(), str(m.service_version()), m.capabilities(), Limits{}};
  if (const wire::Limits* l = m.limits()) {
    out.limits =
        Limits{l->max_payload_bytes(), l->max_image_size(), l->max_layers(), l->max_tile_size()};
  }
  return out;
}

SetView get(const wire::SetView& m) {
  SetView out;
  out.width = m.width();
  out.height = m.height();
  out.hfov_deg = m.hfov_deg();
  out.sinks = m.sinks();
  out.shm_format = static_cast<ShmPixelFormat>(m.shm_format());
  out.file_dir = str(m.file_dir());
  out.file_format = static_cast<FileFormat>(m.file_format());
  out.quality_preset = str(m.quality_preset());
  return out;
}

Pose get(const wire::Pose& m) { return get_pose(m); }

SetTime get(const wire::SetTime& m) { return SetTime{m.utc_unix_s()}; }

WeatherLayers get(const wire::WeatherLayers& m) {
  WeatherLayers out;
  out.map_seed = m.map_seed();
  if (const auto albedo = m.ground_albedo(); albedo.has_value()) out.ground_albedo = *albedo;
  if (const auto visibility = m.visibility_m(); visibility.has_value()) out.visibility_m = *visibility;  // m
  if (const auto* layers = m.layers()) {
    out.layers.reserve(layers->size());
    for (const wire::CloudLayer* l : *layers) {
      // A vector element is a non-null offset (the verifier checked it).
      out.layers.push_back(CloudLayer{l->type(), l->base_m(), l->top_m(), l->coverage(),
                                      l->density_scale(), l->droplet_diameter_um(),
                                      l->wind_east_mps(), l->wind_north_mps(), l->coverage_channel()});
    }
  }
  return out;
}

WeatherMapTile get(const wire::WeatherMapTile& m) {
  WeatherMapTile out;
  out.lat_min_deg = m.lat_min_deg();
  out.lon_min_deg = m.lon_min_deg();
  out.lat_max_deg = m.lat_max_deg();
  out.lon_max_deg = m.lon_max_deg();
  out.width = m.width();
  out.height = m.height();
  out.channels = m.channels();
  out.valid_at_utc_s = m.valid_at_utc_s();
  out.layer_channels = m.layer_channels();
  if (const auto* data = m.data()) {
    out.data.resize(data->size());
    // Little-endian floats on the wire and on every host this builds for (flatbuffers
    // itself assumes it unless FLATBUFFERS_LITTLEENDIAN is 0).
    static_assert(FLATBUFFERS_LITTLEENDIAN, "big-endian hosts need an element-wise copy");
    if (!out.data.empty()) std::memcpy(out.data.data(), data->data(), data->size() * 4);
  }
  return out;
}

RenderRequest get(const wire::RenderRequest& m) { return RenderRequest{m.request_id()}; }

FrameReady get(const wire::FrameReady& m) {
  FrameReady out;
  out.frame_number = m.frame_number();
  out.request_id = m.request_id();
  if (const wire::Pose* p = m.pose()) out.pose = get_pose(*p);
  out.sim_time_s = m.sim_time_s();
  if (const auto slot = m.shm_slot()) out.shm_slot = *slot;
  out.width = m.width();
  out.height = m.height();
  out.render_ms = m.render_ms();
  out.latency_ms = m.latency_ms();
  if (const fb::String* path = m.file_path()) out.file_path = path->str();
  return out;
}

Error get(const wire::Error& m) {
  return Error{static_cast<ErrorCode>(m.code()), str(m.text()), m.answers_seq()};
}

StatsRequest get(const wire::StatsRequest&) { return StatsRequest{}; }

Stats get(const wire::Stats& m) {
  return Stats{m.frames_rendered(), m.fps(), m.poses_received(), m.poses_dropped(), m.clients(),
               m.frame_in_progress_ms()};
}

// The body as a Message; nullopt if the union's table is absent.
template <class W>
std::optional<Message> convert(const void* table) {
  if (table == nullptr) return std::nullopt;
  return Message(get(*static_cast<const W*>(table)));
}

std::optional<Message> convert_body(wire::Body type, const void* table) {
  switch (type) {
    case wire::Body::Hello:
      return convert<wire::Hello>(table);
    case wire::Body::Welcome:
      return convert<wire::Welcome>(table);
    case wire::Body::SetView:
      return convert<wire::SetView>(table);
    case wire::Body::Pose:
      return convert<wire::Pose>(table);
    case wire::Body::SetTime:
      return convert<wire::SetTime>(table);
    case wire::Body::WeatherLayers:
      return convert<wire::WeatherLayers>(table);
    case wire::Body::WeatherMapTile:
      return convert<wire::WeatherMapTile>(table);
    case wire::Body::RenderRequest:
      return convert<wire::RenderRequest>(table);
    case wire::Body::FrameReady:
      return convert<wire::FrameReady>(table);
    case wire::Body::Error:
      return convert<wire::Error>(table);
    case wire::Body::StatsRequest:
      return convert<wire::StatsRequest>(table);
    case wire::Body::Stats:
      return convert<wire::Stats>(table);
    case wire::Body::NONE:
      break;
  }
  return std::nullopt;
}

// Sub-tables the schema leaves optional for extensibility but protocol 1 requires.
std::optional<std::string> missing_required(const wire::Envelope& env) {
  if (const auto* w = env.body_as_Welcome(); w && !w->limits()) {
    return "Welcome.limits is missing";
  }
  if (const auto* f = env.body_as_FrameReady(); f && !f->pose()) {
    return "FrameReady.pose is missing";
  }
  return std::nullopt;
}

DecodeResult failure(std::uint64_t seq, ErrorCode code, std::string text) {
  DecodeResult r;
  r.seq = seq;
  r.error = code;
  r.error_text = std::move(text);
  return r;
}

}  // namespace

DecodeResult decode(std::span<const std::uint8_t> payload) {
  const std::size_t n = payload.size();
  if (n < kMinPayloadBytes) {
    return failure(0, ErrorCode::Malformed,
                   "payload is " + std::to_string(n) + " bytes, too short for an Envelope");
  }
  if (n > kMaxPayloadBytes) {
    return failure(0, ErrorCode::Malformed,
                   "payload is " + std::to_string(n) + " bytes, more than the limit " +
                       std::to_string(kMaxPayloadBytes));
  }
  // The verifier checks alignment relative to the buffer start; the accessors then read
  // scalars in place, so give them an 8-byte aligned copy if the caller's bytes are not.
  std::vector<std::uint64_t> aligned;
  const std::uint8_t* buf = payload.data();
  if (reinterpret_cast<std::uintptr_t>(buf) % alignof(std::uint64_t) != 0) {
    aligned.resize((n + 7) / 8);
    std::memcpy(aligned.data(), buf, n);
    buf = reinterpret_cast<const std::uint8_t*>(aligned.data());
  }

  if (!wire::EnvelopeBufferHasIdentifier(buf)) {
    return failure(0, ErrorCode::Malformed,
                   "payload lacks the file identifier \"CSVP\" at bytes 4..7 "
                   "(not a cloudsvc Envelope)");
  }
  fb::Verifier::Options opts;
  opts.max_depth = kMaxDepth;
  opts.max_tables = kMaxTables;
  opts.check_alignment = true;
  fb::Verifier verifier(buf, n, opts);
  if (!wire::VerifyEnvelopeBuffer(verifier)) {
    return failure(0, ErrorCode::Malformed,
                   "payload failed the FlatBuffers verifier (truncated or corrupt Envelope)");
  }

  const wire::Envelope* env = wire::GetEnvelope(buf);
  const std::uint64_t seq = env->seq();
  const wire::Body type = env->body_type();
  if (type == wire::Body::NONE) {
    return failure(seq, ErrorCode::UnknownMessage, "Envelope.body is empty");
  }
  if (static_cast<unsigned>(type) > static_cast<unsigned>(wire::Body::MAX)) {
    return failure(seq, ErrorCode::UnknownMessage,
                   "Envelope.body type " + std::to_string(static_cast<unsigned>(type)) +
                       " is unknown to protocol " + std::to_string(kProtocolMajor) + "." +
                       std::to_string(kProtocolMinor));
  }
  std::optional<Message> message = convert_body(type, env->body());
  if (!message) {
    return failure(
        seq, ErrorCode::Malformed,
        std::string("Envelope.body names ") + wire::EnumNameBody(type) + " but holds no table");
  }
  if (seq == 0) {
    return failure(seq, ErrorCode::InvalidField, "Envelope.seq is 0 (must be >= 1)");
  }
  if (auto problem = missing_required(*env)) {
    return failure(seq, ErrorCode::InvalidField, std::move(*problem));
  }
  if (auto problem = validate(*message)) {
    return failure(seq, ErrorCode::InvalidField, std::move(*problem));
  }
  DecodeResult r;
  r.seq = seq;
  r.message = std::move(message);
  return r;
}

}  // namespace cloudsvc::protocol
