// C ABI wrapper of ShmFrameReader (protocol/shm/cloudsvc_shm.h). No C++ exception crosses
// the C boundary: each becomes a return code and a message.
#include "protocol/shm/cloudsvc_shm.h"

#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>

#include "protocol/shm/shm_frame_reader.h"

struct cloudsvc_shm_reader {
  cloudsvc::ShmFrameReader reader;
  cloudsvc::ShmFrame frame;
  std::string last_error;  // of the last -3
  explicit cloudsvc_shm_reader(const char* name) : reader(name) {}
};

extern "C" cloudsvc_shm_reader* cloudsvc_shm_open(const char* name, char* error, size_t error_size) {
  try {
    if (!name) throw std::invalid_argument("name is NULL");
    return new cloudsvc_shm_reader(name);
  } catch (const std::exception& e) {
    if (error && error_size) std::snprintf(error, error_size, "%s", e.what());
    return nullptr;
  }
}

extern "C" int cloudsvc_shm_read_latest(cloudsvc_shm_reader* r, uint64_t after_frame, cloudsvc_shm_slot* info,
                                        void* pixels, size_t capacity) {
  if (!r || !info) return -2;
  r->last_error.clear();
  try {
    if (!r->reader.read_latest(after_frame, r->frame)) return 0;
  } catch (const std::exception& e) {  // a corrupt ring, or no memory for the copy
    r->last_error = e.what();
    return -3;
  }
  *info = r->frame.info;
  if (!pixels || capacity < r->frame.pixels.size()) return -1;
  std::memcpy(pixels, r->frame.pixels.data(), r->frame.pixels.size());
  return 1;
}

extern "C" const char* cloudsvc_shm_last_error(const cloudsvc_shm_reader* r) { return r ? r->last_error.c_str() : ""; }

extern "C" void cloudsvc_shm_close(cloudsvc_shm_reader* r) { delete r; }
