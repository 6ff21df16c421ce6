// The flatc-generated code of cloudsvc.fbs (namespace cloudsvc::wire), plus compile-time
// checks that the hand-written messages.h and error_code.h agree with it: a schema edit
// that is not mirrored there fails to compile instead of corrupting messages.
#pragma once

#include <type_traits>
#include <variant>

#include "protocol/cloudsvc_generated.h"  // generated at build time
#include "protocol/error_code.h"
#include "protocol/messages.h"
#include "protocol/shm/shm_layout.h"

namespace cloudsvc::protocol::wire_checks {

namespace w = ::cloudsvc::wire;

// Message alternative i is Body member i + 1.
template <class T, w::Body B, std::size_t I>
constexpr bool kSlot = std::is_same_v<std::variant_alternative_t<I, Message>,
                                      T>&& static_cast<std::size_t>(B) == I + 1;
static_assert(kSlot<Hello, w::Body::Hello, 0>);
static_assert(kSlot<Welcome, w::Body::Welcome, 1>);
static_assert(kSlot<SetView, w::Body::SetView, 2>);
static_assert(kSlot<Pose, w::Body::Pose, 3>);
static_assert(kSlot<SetTime, w::Body::SetTime, 4>);
static_assert(kSlot<WeatherLayers, w::Body::WeatherLayers, 5>);
static_assert(kSlot<WeatherMapTile, w::Body::WeatherMapTile, 6>);
static_assert(kSlot<RenderRequest, w::Body::RenderRequest, 7>);
static_assert(kSlot<FrameReady, w::Body::FrameReady, 8>);
static_assert(kSlot<Error, w::Body::Error, 9>);
static_assert(kSlot<StatsRequest, w::Body::StatsRequest, 10>);
static_assert(kSlot<Stats, w::Body::Stats, 11>);
static_assert(std::variant_size_v<Message> == static_cast<std::size_t>(w::Body::MAX));

static_assert(capability::kSinkShm == static_cast<std::uint32_t>(w::Capability::SinkShm));
static_assert(capability::kSinkWindow == static_cast<std::uint32_t>(w::Capability::SinkWindow));
static_assert(capability::kSinkFile == static_cast<std::uint32_t>(w::Capability::SinkFile));
static_assert(capability::kWeatherTiles == static_cast<std::uint32_t>(w::Capability::WeatherTiles));
static_assert(capability::kRenderRequest ==
              static_cast<std::uint32_t>(w::Capability::RenderRequest));
static_assert(capability::kStats == static_cast<std::uint32_t>(w::Capability::Stats));
static_assert(capability::kAll == static_cast<std::uint32_t>(w::Capability::ANY));

static_assert(sink::kShm == static_cast<std::uint8_t>(w::Sink::Shm));
static_assert(sink::kWindow == static_cast<std::uint8_t>(w::Sink::Window));
static_assert(sink::kFile == static_cast<std::uint8_t>(w::Sink::File));
static_assert(sink::kAll == static_cast<std::uint8_t>(w::Sink::ANY));

static_assert(pose_flag::kTeleport == static_cast<std::uint8_t>(w::PoseFlag::Teleport));
static_assert(pose_flag::kReset == static_cast<std::uint8_t>(w::PoseFlag::Reset));
static_assert(pose_flag::kAll == static_cast<std::uint8_t>(w::PoseFlag::ANY));

static_assert(tile_channel::kCoverage == static_cast<std::uint8_t>(w::TileChannel::Coverage));
static_assert(tile_channel::kVerticalDevelopment ==
              static_cast<std::uint8_t>(w::TileChannel::VerticalDevelopment));
static_assert(tile_channel::kDensity == static_cast<std::uint8_t>(w::TileChannel::Density));
static_assert(tile_channel::kPrecipitation ==
              static_cast<std::uint8_t>(w::TileChannel::Precipitation));
static_assert(tile_channel::kGroundAlbedo == static_cast<std::uint8_t>(w::TileChannel::GroundAlbedo));
static_assert(tile_channel::kAll == static_cast<std::uint8_t>(w::TileChannel::ANY));

static_assert(static_cast<int>(ShmPixelFormat::Rgba16fLinear) ==
              static_cast<int>(w::ShmPixelFormat::Rgba16fLinear));
static_assert(static_cast<int>(ShmPixelFormat::Rgba8Srgb) ==
              static_cast<int>(w::ShmPixelFormat::Rgba8Srgb));
static_assert(static_cast<unsigned>(ShmPixelFormat::Rgba16fLinear) ==
              CLOUDSVC_SHM_RGBA16F_LINEAR);
static_assert(static_cast<unsigned>(ShmPixelFormat::Rgba8Srgb) == CLOUDSVC_SHM_RGBA8_SRGB);
static_assert(static_cast<int>(FileFormat::Png) == static_cast<int>(w::FileFormat::Png));
static_assert(static_cast<int>(FileFormat::Exr) == static_cast<int>(w::FileFormat::Exr));

template <ErrorCode A, w::ErrorCode B>
constexpr bool kSameCode = static_cast<int>(A) == static_cast<int>(B);
static_assert(kSameCode<ErrorCode::Unspecified, w::ErrorCode::Unspecified>);
static_assert(kSameCode<ErrorCode::Malformed, w::ErrorCode::Malformed>);
static_assert(kSameCode<ErrorCode::InvalidField, w::ErrorCode::InvalidField>);
static_assert(kSameCode<ErrorCode::UnknownMessage, w::ErrorCode::UnknownMessage>);
static_assert(kSameCode<ErrorCode::UnexpectedMessage, w::ErrorCode::UnexpectedMessage>);
static_assert(kSameCode<ErrorCode::HandshakeRequired, w::ErrorCode::HandshakeRequired>);
static_assert(kSameCode<ErrorCode::VersionMismatch, w::ErrorCode::VersionMismatch>);
static_assert(kSameCode<ErrorCode::FramingError, w::ErrorCode::FramingError>);
static_assert(kSameCode<ErrorCode::UnknownPreset, w::ErrorCode::UnknownPreset>);
static_assert(kSameCode<ErrorCode::SinkUnavailable, w::ErrorCode::SinkUnavailable>);
static_assert(kSameCode<ErrorCode::CapabilityMissing, w::ErrorCode::CapabilityMissing>);
static_assert(kSameCode<ErrorCode::Busy, w::ErrorCode::Busy>);
static_assert(kSameCode<ErrorCode::RenderFailed, w::ErrorCode::RenderFailed>);
static_assert(kSameCode<ErrorCode::Internal, w::ErrorCode::Internal>);
static_assert(kSameCode<ErrorCode::Overloaded, w::ErrorCode::Overloaded>);
static_assert(kSameCode<ErrorCode::IdleTimeout, w::ErrorCode::IdleTimeout>);
static_assert(kSameCode<ErrorCode::IdleTimeout, w::ErrorCode::MAX>);

}  // namespace cloudsvc::protocol::wire_checks
