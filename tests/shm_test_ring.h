// A shared-memory frame ring laid out by a test itself (protocol/shm/shm_layout.h), so that the
// readers can be fed well-formed and hostile headers: a POSIX shm object with a name unique
// to the test process, mapped read-write, unlinked when the TestRing goes away.
#pragma once

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "protocol/shm/shm_layout.h"

namespace cloudsvc::test {

class TestRing {
 public:
  // A consistent ring: `slots` slots for frames up to max_width x max_height (8 bytes per
  // pixel, as the service sizes them), one RGBA8 frame of width x height in slot
  // `latest` published as frame 5. Every field can be spoiled afterwards through header()
  // and slot(i).
  TestRing(const std::string& tag, std::uint32_t max_width, std::uint32_t max_height, std::uint32_t slots = 2)
      : name_("cloudsvc-test-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(++counter())) {
    const std::uint64_t stride = CLOUDSVC_SHM_SLOT_HEADER_BYTES + std::uint64_t{max_width} * max_height * 8;
    bytes_ = CLOUDSVC_SHM_HEADER_BYTES + stride * slots;
    map(bytes_);
    cloudsvc_shm_header* h = header();
    h->magic = CLOUDSVC_SHM_MAGIC;
    h->version = CLOUDSVC_SHM_VERSION;
    h->header_bytes = CLOUDSVC_SHM_HEADER_BYTES;
    h->slot_count = slots;
    h->slot_stride = stride;
    h->max_width = max_width;
    h->max_height = max_height;
    h->writer_pid = static_cast<std::uint32_t>(::getpid());
    publish(slots - 1, max_width, max_height);
  }
  // A segment of `bytes` bytes holding only a header copied from `h` (sizes as given, no
  // slots written): for headers whose sizes do not describe a ring at all.
  TestRing(const std::string& tag, const cloudsvc_shm_header& h, std::size_t bytes)
      : name_("cloudsvc-test-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(++counter())) {
    bytes_ = bytes;
    map(bytes_);
    std::memcpy(base_, &h, sizeof h < bytes ? sizeof h : bytes);
  }
  ~TestRing() {
    if (base_) ::munmap(base_, bytes_);
    ::shm_unlink(("/" + name_).c_str());
  }
  TestRing(const TestRing&) = delete;
  TestRing& operator=(const TestRing&) = delete;

  const std::string& name() const { return name_; }
  std::size_t bytes() const { return bytes_; }
  cloudsvc_shm_header* header() { return reinterpret_cast<cloudsvc_shm_header*>(base_); }
  cloudsvc_shm_slot* slot(std::uint32_t i) {
    const cloudsvc_shm_header* h = header();
    return reinterpret_cast<cloudsvc_shm_slot*>(base_ + h->header_bytes + h->slot_stride * i);
  }

  // Writes a complete RGBA8 frame of width x height into slot i (pixel bytes i + 1) and
  // makes it the newest, frame 5.
  void publish(std::uint32_t i, std::uint32_t width, std::uint32_t height) {
    cloudsvc_shm_slot* s = slot(i);
    s->seq = 2;  // even: complete
    s->frame_number = 5;
    s->width = width;
    s->height = height;
    s->pixel_format = CLOUDSVC_SHM_RGBA8_SRGB;
    s->row_bytes = width * 4;
    s->pixel_bytes = std::uint64_t{s->row_bytes} * height;
    std::memset(reinterpret_cast<std::uint8_t*>(s) + CLOUDSVC_SHM_SLOT_HEADER_BYTES, static_cast<int>(i + 1),
                s->pixel_bytes);
    header()->latest_slot = i;
    header()->latest_frame = 5;
  }

 private:
  static int& counter() {
    static int n = 0;
    return n;
  }
  void map(std::size_t bytes) {
    const std::string path = "/" + name_;
    const int fd = ::shm_open(path.c_str(), O_RDWR | O_CREAT | O_EXCL, 0600);
    if (fd < 0) throw std::runtime_error("shm_open " + path + " failed");
    if (::ftruncate(fd, static_cast<off_t>(bytes)) != 0) {
      ::close(fd);
      ::shm_unlink(path.c_str());
      throw std::runtime_error("ftruncate " + path + " failed");
    }
    void* p = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    ::close(fd);
    if (p == MAP_FAILED) {
      ::shm_unlink(path.c_str());
      throw std::runtime_error("mmap " + path + " failed");
    }
    base_ = static_cast<std::uint8_t*>(p);
  }

  std::string name_;
  std::size_t bytes_ = 0;
  std::uint8_t* base_ = nullptr;
};

}  // namespace cloudsvc::test
