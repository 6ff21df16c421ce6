// Protocol version of the cloudsvc wire format (docs/PROTOCOL.md, "Versions").
// Major: incompatible change (a connection with a different major is refused).
// Minor: compatible addition (new table fields, new messages, new enum values); peers use
// the smaller of the two minors.
#pragma once

#include <cstdint>

namespace cloudsvc::protocol {

inline constexpr std::uint16_t kProtocolMajor = 1;
inline constexpr std::uint16_t kProtocolMinor = 2;

}  // namespace cloudsvc::protocol
