#include "protocol/messages.h"

#include <bit>

#include "protocol/limits.h"

namespace cloudsvc::protocol {

Limits protocol_limits() {
  return Limits{kMaxPayloadBytes, kMaxImageSize, static_cast<std::uint8_t>(kMaxLayers),
                kMaxTileSize};
}

int WeatherMapTile::channel_count() const {
  return std::popcount(static_cast<unsigned>(channels)) + std::popcount(static_cast<unsigned>(layer_channels));
}

namespace {

template <class T>
constexpr std::string_view kName = "";
template <>
constexpr std::string_view kName<Hello> = "Hello";
template <>
constexpr std::string_view kName<Welcome> = "Welcome";
template <>
constexpr std::string_view kName<SetView> = "SetView";
template <>
constexpr std::string_view kName<Pose> = "Pose";
template <>
constexpr std::string_view kName<SetTime> = "SetTime";
template <>
constexpr std::string_view kName<WeatherLayers> = "WeatherLayers";
template <>
constexpr std::string_view kName<WeatherMapTile> = "WeatherMapTile";
template <>
constexpr std::string_view kName<RenderRequest> = "RenderRequest";
template <>
constexpr std::string_view kName<FrameReady> = "FrameReady";
template <>
constexpr std::string_view kName<Error> = "Error";
template <>
constexpr std::string_view kName<StatsRequest> = "StatsRequest";
template <>
constexpr std::string_view kName<Stats> = "Stats";

}  // namespace

std::string_view message_name(const Message& m) {
  return std::visit([](const auto& v) { return kName<std::decay_t<decltype(v)>>; }, m);
}

Sender sender_of(const Message& m) {
  if (std::holds_alternative<Error>(m)) return Sender::Either;
  if (std::holds_alternative<Welcome>(m) || std::holds_alternative<FrameReady>(m) ||
      std::holds_alternative<Stats>(m)) {
    return Sender::Service;
  }
  return Sender::Client;
}

}  // namespace cloudsvc::protocol
