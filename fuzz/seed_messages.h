// Example protocol messages for the generated seed corpora of the protocol fuzz targets
// (make_seeds.cpp): one valid message of every type, and a few that the service refuses
// (validate() or, for a Hello of another major version, the handshake).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "protocol/messages.h"

namespace cloudsvc::fuzz {

// (name, message) pairs; the names become seed file names.
std::vector<std::pair<std::string, protocol::Message>> valid_seed_messages();
std::vector<std::pair<std::string, protocol::Message>> invalid_seed_messages();

}  // namespace cloudsvc::fuzz
