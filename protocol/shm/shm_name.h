// Names of shared-memory frame rings: ring NAME is the POSIX shared-memory object "/NAME"
// (shm_open). One rule for the writer (ShmFrameWriter), `cloudsvc serve --shm` and
// `sim_client watch --shm`.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace cloudsvc {

inline constexpr std::size_t kMaxShmNameChars = 200;

// True if `name` is 1..200 characters from ASCII letters, digits, '-', '_', '.' and is
// neither "." nor "..".
bool valid_shm_name(std::string_view name);

// The rule for messages: "1..200 characters from letters, digits, '-', '_', '.' (not . or ..)".
std::string shm_name_rule();

}  // namespace cloudsvc
