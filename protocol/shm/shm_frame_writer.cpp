// The ring writer (shm_frame_writer.h); the publishing sequence is in shm_layout.h.
#include "protocol/shm/shm_frame_writer.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <stdexcept>

#include "protocol/shm/shm_name.h"

namespace cloudsvc {

namespace {

std::string shm_path(const std::string& name) { return "/" + name; }

// A segment left by a process that no longer runs may be replaced; a live owner may not.
void remove_stale_segment(const std::string& path) {
  const int fd = ::shm_open(path.c_str(), O_RDONLY, 0);
  if (fd < 0) return;
  cloudsvc_shm_header h{};
  const ssize_t n = ::pread(fd, &h, sizeof h, 0);
  ::close(fd);
  if (n == static_cast<ssize_t>(sizeof h) && h.magic == CLOUDSVC_SHM_MAGIC && h.writer_pid != 0 &&
      static_cast<pid_t>(h.writer_pid) != ::getpid() && ::kill(static_cast<pid_t>(h.writer_pid), 0) == 0) {
    throw std::runtime_error("shared memory " + path + " is in use by cloudsvc process " +
                             std::to_string(h.writer_pid));
  }
  ::shm_unlink(path.c_str());
}

}  // namespace

ShmFrameWriter::ShmFrameWriter(const std::string& name, int max_width, int max_height, unsigned mode, int slot_count)
    : name_(name), max_width_(max_width), max_height_(max_height), slot_count_(static_cast<std::uint32_t>(slot_count)) {
  if (!valid_shm_name(name)) throw std::runtime_error("shared memory name " + name + ": expected " + shm_name_rule());
  if (max_width < 1 || max_height < 1 || slot_count < 2) throw std::runtime_error("shm: bad ring size");
  const std::string path = shm_path(name);
  remove_stale_segment(path);
  const std::uint64_t stride =
      CLOUDSVC_SHM_SLOT_HEADER_BYTES + ((static_cast<std::uint64_t>(max_width) * max_height * 8 + 4095) / 4096) * 4096;
  bytes_ = CLOUDSVC_SHM_HEADER_BYTES + stride * slot_count_;
  const int fd = ::shm_open(path.c_str(), O_RDWR | O_CREAT | O_EXCL, 0600);
  if (fd < 0) throw std::runtime_error("shm_open " + path + ": " + std::strerror(errno));
  // shm_open applied the umask to 0600; fchmod sets exactly `mode`, before any frame is in it.
  if (::fchmod(fd, static_cast<mode_t>(mode & 0777)) != 0) {
    const int e = errno;
    ::close(fd);
    ::shm_unlink(path.c_str());
    throw std::runtime_error("fchmod " + path + ": " + std::strerror(e));
  }
  if (::ftruncate(fd, static_cast<off_t>(bytes_)) != 0) {
    const int e = errno;
    ::close(fd);
    ::shm_unlink(path.c_str());
    throw std::runtime_error("ftruncate " + path + ": " + std::strerror(e));
  }
  void* p = ::mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  ::close(fd);
  if (p == MAP_FAILED) {
    ::shm_unlink(path.c_str());
    throw std::runtime_error("mmap " + path + ": " + std::strerror(errno));
  }
  base_ = static_cast<std::uint8_t*>(p);
  auto* h = reinterpret_cast<cloudsvc_shm_header*>(base_);
  h->version = CLOUDSVC_SHM_VERSION;
  h->header_bytes = CLOUDSVC_SHM_HEADER_BYTES;
  h->slot_count = slot_count_;
  h->slot_stride = stride;
  h->max_width = static_cast<std::uint32_t>(max_width);
  h->max_height = static_cast<std::uint32_t>(max_height);
  h->writer_pid = static_cast<std::uint32_t>(::getpid());
  std::atomic_ref<std::uint32_t>(h->magic).store(CLOUDSVC_SHM_MAGIC, std::memory_order_release);
}

void ShmFrameWriter::unlink_name() const { ::shm_unlink(shm_path(name_).c_str()); }

ShmFrameWriter::~ShmFrameWriter() {
  if (base_) ::munmap(base_, bytes_);
  ::shm_unlink(shm_path(name_).c_str());
}

std::uint32_t ShmFrameWriter::write(const ShmFrameMeta& meta, std::uint32_t pixel_format, int width, int height,
                                    const void* pixels, std::size_t row_bytes) {
  if (width < 1 || height < 1 || width > max_width_ || height > max_height_)
    throw std::runtime_error("shm: frame " + std::to_string(width) + "x" + std::to_string(height) +
                             " exceeds the segment's " + std::to_string(max_width_) + "x" + std::to_string(max_height_));
  auto* h = reinterpret_cast<cloudsvc_shm_header*>(base_);
  const std::uint32_t index = next_slot_;
  next_slot_ = (next_slot_ + 1) % slot_count_;
  std::uint8_t* slot_base = base_ + h->header_bytes + h->slot_stride * index;
  auto* slot = reinterpret_cast<cloudsvc_shm_slot*>(slot_base);
  std::atomic_ref<std::uint64_t> seq(slot->seq);
  const std::uint64_t s = seq.load(std::memory_order_relaxed);
  seq.store(s + 1, std::memory_order_relaxed);  // odd: writing
  std::atomic_thread_fence(std::memory_order_release);
  slot->frame_number = meta.frame_number;
  slot->sim_time_s = meta.sim_time_s;
  slot->unix_time_s = meta.unix_time_s;
  slot->lat_deg = meta.lat_deg;
  slot->lon_deg = meta.lon_deg;
  slot->alt_m = meta.alt_m;
  slot->heading_deg = meta.heading_deg;
  slot->pitch_deg = meta.pitch_deg;
  slot->roll_deg = meta.roll_deg;
  slot->render_ms = meta.render_ms;
  slot->width = static_cast<std::uint32_t>(width);
  slot->height = static_cast<std::uint32_t>(height);
  slot->pixel_format = pixel_format;
  slot->row_bytes = static_cast<std::uint32_t>(row_bytes);
  slot->pixel_bytes = static_cast<std::uint64_t>(row_bytes) * height;
  std::memcpy(slot_base + CLOUDSVC_SHM_SLOT_HEADER_BYTES, pixels, row_bytes * static_cast<std::size_t>(height));
  timespec now{};
  ::clock_gettime(CLOCK_REALTIME, &now);
  slot->publish_unix_ns = static_cast<std::int64_t>(now.tv_sec) * 1000000000 + now.tv_nsec;
  seq.store(s + 2, std::memory_order_release);  // even: complete
  std::atomic_ref<std::uint32_t>(h->latest_slot).store(index, std::memory_order_release);
  std::atomic_ref<std::uint64_t>(h->latest_frame).store(meta.frame_number, std::memory_order_release);
  return index;
}

}  // namespace cloudsvc
