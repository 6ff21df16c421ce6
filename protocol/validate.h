// Semantic validation of messages: every float finite, every field in its range, sizes and
// orderings consistent (limits.h). decode() runs it on every message it accepts; senders
// may run it before encoding.
#pragma once

#include <optional>
#include <string>

#include "protocol/messages.h"

namespace cloudsvc::protocol {

// nullopt when the message is valid; otherwise one line naming the first offending field,
// e.g. "Pose.lat_deg 91 out of range [-90, 90]" or
// "WeatherLayers.layers[1].base_m 1500 below layers[0].top_m 2000 (layers overlap)".
// The matching error code is ErrorCode::InvalidField.
std::optional<std::string> validate(const Message& m);

}  // namespace cloudsvc::protocol
