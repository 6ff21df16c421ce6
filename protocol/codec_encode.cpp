// encode(): Message -> FlatBuffers Envelope.
#include "protocol/codec.h"
#include "protocol/wire.h"

namespace cloudsvc::protocol {
namespace {

namespace fb = flatbuffers;
using Builder = fb::FlatBufferBuilder;

// Absent when empty: readers see an absent string as "".
fb::Offset<fb::String> str(Builder& b, const std::string& s) {
  return s.empty() ? fb::Offset<fb::String>() : b.CreateString(s);
}

fb::Offset<wire::Pose> put_pose(Builder& b, const Pose& p) {
  wire::PoseBuilder pb(b);
  pb.add_sim_time_s(p.sim_time_s);
  if (p.utc_unix_s) pb.add_utc_unix_s(*p.utc_unix_s);
  pb.add_lat_deg(p.lat_deg);
  pb.add_lon_deg(p.lon_deg);
  pb.add_alt_m(p.alt_m);
  pb.add_heading_deg(p.heading_deg);
  pb.add_pitch_deg(p.pitch_deg);
  pb.add_roll_deg(p.roll_deg);
  if (p.velocity_enu) {
    const wire::Vec3 v(p.velocity_enu->east_mps, p.velocity_enu->north_mps, p.velocity_enu->up_mps);
    pb.add_velocity_enu(&v);
  }
  pb.add_flags(p.flags);
  return pb.Finish();
}

struct BodyWriter {
  Builder& b;

  fb::Offset<void> operator()(const Hello& m) {
    return wire::CreateHello(b, m.major, m.minor, str(b, m.client_name), m.capabilities).Union();
  }
  fb::Offset<void> operator()(const Welcome& m) {
    const auto version = str(b, m.service_version);
    const auto limits = wire::CreateLimits(b, m.limits.max_payload_bytes, m.limits.max_image_size,
                                           m.limits.max_layers, m.limits.max_tile_size);
    return wire::CreateWelcome(b, m.major, m.minor, version, m.capabilities, limits).Union();
  }
  fb::Offset<void> operator()(const SetView& m) {
    const auto dir = str(b, m.file_dir);
    const auto preset = str(b, m.quality_preset);
    return wire::CreateSetView(b, m.width, m.height, m.hfov_deg, m.sinks,
                               static_cast<wire::ShmPixelFormat>(m.shm_format), dir,
                               static_cast<wire::FileFormat>(m.file_format), preset)
        .Union();
  }
  fb::Offset<void> operator()(const Pose& m) { return put_pose(b, m).Union(); }
  fb::Offset<void> operator()(const SetTime& m) {
    return wire::CreateSetTime(b, m.utc_unix_s).Union();
  }
  fb::Offset<void> operator()(const WeatherLayers& m) {
    std::vector<fb::Offset<wire::CloudLayer>> layers;
    layers.reserve(m.layers.size());
    for (const CloudLayer& l : m.layers) {
      layers.push_back(wire::CreateCloudLayer(b, l.type, l.base_m, l.top_m, l.coverage,
                                              l.density_scale, l.droplet_diameter_um,
                                              l.wind_east_mps, l.wind_north_mps, l.coverage_channel));
    }
    const fb::Optional<double> albedo = m.ground_albedo ? fb::Optional<double>(*m.ground_albedo) : fb::nullopt;
    const fb::Optional<double> visibility = m.visibility_m ? fb::Optional<double>(*m.visibility_m) : fb::nullopt;
    return wire::CreateWeatherLayers(b, b.CreateVector(layers), m.map_seed, albedo, visibility).Union();
  }
  fb::Offset<void> operator()(const WeatherMapTile& m) {
    const auto data = b.CreateVector(m.data);
    return wire::CreateWeatherMapTile(b, m.lat_min_deg, m.lon_min_deg, m.lat_max_deg, m.lon_max_deg,
                                      m.width, m.height, m.channels, m.valid_at_utc_s, data,
                                      m.layer_channels)
        .Union();
  }
  fb::Offset<void> operator()(const RenderRequest& m) {
    return wire::CreateRenderRequest(b, m.request_id).Union();
  }
  fb::Offset<void> operator()(const FrameReady& m) {
    const auto pose = put_pose(b, m.pose);
    const auto path = m.file_path ? b.CreateString(*m.file_path) : fb::Offset<fb::String>();
    const fb::Optional<std::uint32_t> slot =
        m.shm_slot ? fb::Optional<std::uint32_t>(*m.shm_slot) : fb::nullopt;
    return wire::CreateFrameReady(b, m.frame_number, m.request_id, pose, m.sim_time_s, slot,
                                  m.width, m.height, m.render_ms, m.latency_ms, path)
        .Union();
  }
  fb::Offset<void> operator()(const Error& m) {
    return wire::CreateError(b, static_cast<wire::ErrorCode>(m.code), str(b, m.text), m.answers_seq)
        .Union();
  }
  fb::Offset<void> operator()(const StatsRequest&) { return wire::CreateStatsRequest(b).Union(); }
  fb::Offset<void> operator()(const Stats& m) {
    return wire::CreateStats(b, m.frames_rendered, m.fps, m.poses_received, m.poses_dropped,
                             m.clients, m.frame_in_progress_ms)
        .Union();
  }
};

std::size_t initial_size(const Message& m) {
  if (const auto* tile = std::get_if<WeatherMapTile>(&m)) {
    return 256 + tile->data.size() * sizeof(float);
  }
  return 512;
}

}  // namespace

std::vector<std::uint8_t> encode(const Message& m, std::uint64_t seq) {
  Builder b(initial_size(m));
  const fb::Offset<void> body = std::visit(BodyWriter{b}, m);
  const auto type = static_cast<wire::Body>(m.index() + 1);
  wire::FinishEnvelopeBuffer(b, wire::CreateEnvelope(b, seq, type, body));
  const fb::span<const std::uint8_t> out = b.GetBufferSpan();
  return std::vector<std::uint8_t>(out.data(), out.data() + out.size());
}

}  // namespace cloudsvc::protocol
