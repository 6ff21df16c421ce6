// The ring reader (shm_frame_reader.h); the reading sequence is in shm_layout.h.
#include "protocol/shm/shm_frame_reader.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace cloudsvc {

namespace {

template <class T>
T load_acquire(const T& field) {
  return std::atomic_ref<T>(const_cast<T&>(field)).load(std::memory_order_acquire);
}

// Attempts at copying a slot that keeps being rewritten under the reader before giving up
// for this call (the writer lapping a reader 1000 times in a row means the reader is far
// too slow; the next call starts afresh).
constexpr int kCopyAttempts = 1000;

}  // namespace

ShmFrameReader::ShmFrameReader(const std::string& name) : path_("/" + name) {
  const int fd = ::shm_open(path_.c_str(), O_RDONLY, 0);
  if (fd < 0)
    throw std::runtime_error("shared memory " + path_ + ": " + std::strerror(errno) + " (is cloudsvc serve --shm " +
                             name + " running?)");
  struct stat st{};
  if (::fstat(fd, &st) != 0 || st.st_size < static_cast<off_t>(CLOUDSVC_SHM_HEADER_BYTES)) {
    ::close(fd);
    throw std::runtime_error("shared memory " + path_ + ": too small to be a cloudsvc frame ring (" +
                             std::to_string(st.st_size) + " bytes, the header alone takes " +
                             std::to_string(CLOUDSVC_SHM_HEADER_BYTES) + ")");
  }
  // The segment's size now is what gets mapped: every size in the header is checked
  // against it, never against what the header claims.
  bytes_ = static_cast<std::size_t>(st.st_size);
  void* p = ::mmap(nullptr, bytes_, PROT_READ, MAP_SHARED, fd, 0);
  ::close(fd);
  if (p == MAP_FAILED) throw std::runtime_error("mmap " + path_ + ": " + std::strerror(errno));
  base_ = static_cast<const std::uint8_t*>(p);
  // The writer stores magic last (release): once it is seen, the rest of the header is.
  const auto* live = reinterpret_cast<const cloudsvc_shm_header*>(base_);
  cloudsvc_shm_header header{};
  header.magic = load_acquire(live->magic);
  std::memcpy(reinterpret_cast<std::uint8_t*>(&header) + sizeof header.magic,
              base_ + sizeof header.magic, sizeof header - sizeof header.magic);
  if (auto problem = ring_geometry_problem(header, bytes_, geometry_)) {
    ::munmap(const_cast<std::uint8_t*>(base_), bytes_);
    base_ = nullptr;
    throw std::runtime_error("shared memory " + path_ + ": " + *problem);
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

void ShmFrameReader::fail_corrupt(const std::string& problem) const {
  throw std::runtime_error("shared memory " + path_ + ": " + problem);
}

bool ShmFrameReader::copy_latest(std::uint64_t after_frame, cloudsvc_shm_slot& info,
                                 std::vector<std::uint8_t>* pixels) {
  const auto* h = reinterpret_cast<const cloudsvc_shm_header*>(base_);
  for (int attempt = 0; attempt < kCopyAttempts; ++attempt) {
    if (load_acquire(h->latest_frame) <= after_frame) return false;
    const std::uint32_t index = load_acquire(h->latest_slot);
    if (index >= geometry_.slot_count)  // one atomic word, never torn: the ring is corrupt
      fail_corrupt("latest_slot " + std::to_string(index) + " outside the ring's " +
                   std::to_string(geometry_.slot_count) + " slots");
    // In bounds: geometry_ was checked so that every slot lies inside the mapping.
    const std::uint8_t* slot_base = base_ + geometry_.slot_offset(index);
    const auto* slot = reinterpret_cast<const cloudsvc_shm_slot*>(slot_base);
    std::atomic_ref<std::uint64_t> seq(const_cast<std::uint64_t&>(slot->seq));
    const std::uint64_t s1 = seq.load(std::memory_order_acquire);
    if (s1 & 1u) continue;  // being written
    std::memcpy(&info, slot, sizeof(cloudsvc_shm_slot));
    const std::optional<std::string> problem = slot_problem(info, geometry_);
    if (!problem && pixels) {
      pixels->resize(info.pixel_bytes);  // <= the slot's pixel capacity: checked
      std::memcpy(pixels->data(), slot_base + CLOUDSVC_SHM_SLOT_HEADER_BYTES, info.pixel_bytes);
    }
    std::atomic_thread_fence(std::memory_order_acquire);
    if (seq.load(std::memory_order_relaxed) != s1) continue;  // torn: the writer lapped us
    // A stable, complete slot whose sizes disagree with the ring was written that way.
    if (problem)
      fail_corrupt("slot " + std::to_string(index) + " (frame " + std::to_string(info.frame_number) + "): " +
                   *problem);
    info.seq = s1;
    return info.frame_number > after_frame;
  }
  return false;
}

bool ShmFrameReader::read_latest(std::uint64_t after_frame, ShmFrame& out) {
  return copy_latest(after_frame, out.info, &out.pixels);
}

bool ShmFrameReader::read_latest_header(std::uint64_t after_frame, cloudsvc_shm_slot& out) {
  return copy_latest(after_frame, out, nullptr);
}

}  // namespace cloudsvc
