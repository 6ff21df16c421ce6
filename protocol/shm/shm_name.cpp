// Ring names (shm_name.h).
#include "protocol/shm/shm_name.h"

namespace cloudsvc {

namespace {

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
         c == '.';
}

}  // namespace

bool valid_shm_name(std::string_view name) {
  if (name.empty() || name.size() > kMaxShmNameChars || name == "." || name == "..") return false;
  for (char c : name)
    if (!is_name_char(c)) return false;
  return true;
}

std::string shm_name_rule() {
  return "1.." + std::to_string(kMaxShmNameChars) + " characters from letters, digits, '-', '_', '.' (not . or ..)";
}

}  // namespace cloudsvc
