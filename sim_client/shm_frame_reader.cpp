#include "sim_client/shm_frame_reader.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace cloudsvc::client {

namespace {
template <class T>
T load_acquire(const T& field) {
  return std::atomic_ref<T>(const_cast<T&>(field)).load(std::memory_order_acquire);
}
}  // namespace

ShmFrameReader::ShmFrameReader(const std::string& name) {
  const std::string path = "/" + name;
  const int fd = ::shm_open(path.c_str(), O_RDONLY, 0);
  if (fd < 0) throw std::runtime_error("shared memory " + path + ": " + std::strerror(errno) + " (is cloudsvc serve --shm " + name + " running?)");
  struct stat st{};
  if (::fstat(fd, &st) != 0 || st.st_size < static_cast<off_t>(CLOUDSVC_SHM_HEADER_BYTES)) {
    ::close(fd);
    throw std::runtime_error("shared memory " + path + ": too small to be a cloudsvc frame ring");
  }
  bytes_ = static_cast<std::size_t>(st.st_size);
  void* p = ::mmap(nullptr, bytes_, PROT_READ, MAP_SHARED, fd, 0);
  ::close(fd);
  if (p == MAP_FAILED) throw std::runtime_error("mmap " + path + ": " + std::strerror(errno));
  base_ = static_cast<const std::uint8_t*>(p);
  const auto* h = reinterpret_cast<const cloudsvc_shm_header*>(base_);
  const std::uint32_t magic = load_acquire(h->magic);
  std::string problem;
  if (magic != CLOUDSVC_SHM_MAGIC) problem = "not a cloudsvc frame ring (bad magic)";
  else if (h->version != CLOUDSVC_SHM_VERSION) problem = "unsupported ring version " + std::to_string(h->version);
  else if (h->header_bytes + h->slot_stride * h->slot_count > bytes_) problem = "ring larger than the segment";
  if (!problem.empty()) {
    ::munmap(const_cast<std::uint8_t*>(base_), bytes_);
    throw std::runtime_error("shared memory " + path + ": " + problem);
  }
}

ShmFrameReader::~ShmFrameReader() {
  if (base_) ::munmap(const_cast<std::uint8_t*>(base_), bytes_);
}

std::uint64_t ShmFrameReader::latest_frame() const {
  return load_acquire(reinterpret_cast<const cloudsvc_shm_header*>(base_)->latest_frame);
}

std::uint32_t ShmFrameReader::writer_pid() const {
  return reinterpret_cast<const cloudsvc_shm_header*>(base_)->writer_pid;
}

bool ShmFrameReader::read_latest(std::uint64_t after_frame, ShmFrame& out) {
  const auto* h = reinterpret_cast<const cloudsvc_shm_header*>(base_);
  for (int attempt = 0; attempt < 1000; ++attempt) {
    if (load_acquire(h->latest_frame) <= after_frame) return false;
    const std::uint32_t index = load_acquire(h->latest_slot);
    if (index >= h->slot_count) return false;
    const std::uint8_t* slot_base = base_ + h->header_bytes + h->slot_stride * index;
    const auto* slot = reinterpret_cast<const cloudsvc_shm_slot*>(slot_base);
    const std::uint64_t s1 = load_acquire(slot->seq);
    if (s1 & 1u) continue;  // being written
    std::memcpy(&out.info, slot, sizeof(cloudsvc_shm_slot));
    const std::uint64_t bytes = out.info.pixel_bytes;
    if (bytes > h->slot_stride - CLOUDSVC_SHM_SLOT_HEADER_BYTES) continue;  // inconsistent: retry
    out.pixels.resize(bytes);
    std::memcpy(out.pixels.data(), slot_base + CLOUDSVC_SHM_SLOT_HEADER_BYTES, bytes);
    std::atomic_thread_fence(std::memory_order_acquire);
    const std::uint64_t s2 = std::atomic_ref<std::uint64_t>(const_cast<std::uint64_t&>(slot->seq)).load(std::memory_order_relaxed);
    if (s1 != s2) continue;  // torn: the writer lapped us
    out.info.seq = s1;
    if (out.info.frame_number <= after_frame) return false;
    return true;
  }
  return false;
}

bool ShmFrameReader::read_latest_header(std::uint64_t after_frame, cloudsvc_shm_slot& out) {
  const auto* h = reinterpret_cast<const cloudsvc_shm_header*>(base_);
  for (int attempt = 0; attempt < 1000; ++attempt) {
    if (load_acquire(h->latest_frame) <= after_frame) return false;
    const std::uint32_t index = load_acquire(h->latest_slot);
    if (index >= h->slot_count) return false;
    const auto* slot = reinterpret_cast<const cloudsvc_shm_slot*>(base_ + h->header_bytes + h->slot_stride * index);
    const std::uint64_t s1 = load_acquire(slot->seq);
    if (s1 & 1u) continue;  // being written
    std::memcpy(&out, slot, sizeof(cloudsvc_shm_slot));
    std::atomic_thread_fence(std::memory_order_acquire);
    const std::uint64_t s2 = std::atomic_ref<std::uint64_t>(const_cast<std::uint64_t&>(slot->seq)).load(std::memory_order_relaxed);
    if (s1 != s2) continue;  // torn: the writer lapped us
    out.seq = s1;
    return out.frame_number > after_frame;
  }
  return false;
}

}  // namespace cloudsvc::client
