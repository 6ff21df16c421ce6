/* The shared-memory reader's C ABI (protocol/shm/cloudsvc_shm.h, layout protocol/shm/shm_layout.h)
 * compiled as C99, not C++: this program lays out a two-slot ring itself, following only
 * the C header, and reads it back through cloudsvc_shm_open / cloudsvc_shm_read_latest /
 * cloudsvc_shm_close. Exit code 0 when every check passes; each failure prints one line. */
#define _POSIX_C_SOURCE 200809L

#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "protocol/shm/cloudsvc_shm.h"

static int failures = 0;
#define CHECK(cond)                                              \
  do {                                                           \
    if (!(cond)) {                                               \
      printf("%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
      ++failures;                                                \
    }                                                            \
  } while (0)

int main(void) {
  char err[256] = "";
  char name[64];
  snprintf(name, sizeof name, "cloudsvc-test-c-abi-%d", (int)getpid());

  CHECK(cloudsvc_shm_open("cloudsvc-test-c-abi-absent", err, sizeof err) == NULL);
  CHECK(strlen(err) > 0);
  cloudsvc_shm_slot info;
  CHECK(cloudsvc_shm_read_latest(NULL, 0, &info, NULL, 0) == -2);

  /* A ring of 2 slots for frames up to 4x2 RGBA8 (32 bytes of pixels per slot). */
  const uint64_t stride = CLOUDSVC_SHM_SLOT_HEADER_BYTES + 4096;
  const size_t bytes = CLOUDSVC_SHM_HEADER_BYTES + 2 * stride;
  char path[80];
  snprintf(path, sizeof path, "/%s", name);
  const int fd = shm_open(path, O_RDWR | O_CREAT | O_EXCL, 0600);
  if (fd < 0 || ftruncate(fd, (off_t)bytes) != 0) {
    printf("cannot create %s\n", path);
    return 1;
  }
  unsigned char* base = mmap(NULL, bytes, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  close(fd);
  if (base == MAP_FAILED) {
    shm_unlink(path);
    printf("cannot map %s\n", path);
    return 1;
  }
  cloudsvc_shm_header* h = (cloudsvc_shm_header*)base;
  h->version = CLOUDSVC_SHM_VERSION;
  h->header_bytes = CLOUDSVC_SHM_HEADER_BYTES;
  h->slot_count = 2;
  h->slot_stride = stride;
  h->max_width = 4;
  h->max_height = 2;
  h->writer_pid = (uint32_t)getpid();
  unsigned char* slot_base = base + CLOUDSVC_SHM_HEADER_BYTES + stride * 1;
  cloudsvc_shm_slot* s = (cloudsvc_shm_slot*)slot_base;
  s->seq = 2; /* even: complete */
  s->frame_number = 7;
  s->lat_deg = 47.5;
  s->heading_deg = 271.0;
  s->width = 4;
  s->height = 2;
  s->pixel_format = CLOUDSVC_SHM_RGBA8_SRGB;
  s->row_bytes = 16;
  s->pixel_bytes = 32;
  s->publish_unix_ns = 1782043200123456789LL;
  for (int i = 0; i < 32; ++i) slot_base[CLOUDSVC_SHM_SLOT_HEADER_BYTES + i] = (unsigned char)(i * 3);
  h->latest_slot = 1;
  h->latest_frame = 7;
  h->magic = CLOUDSVC_SHM_MAGIC;

  cloudsvc_shm_reader* r = cloudsvc_shm_open(name, err, sizeof err);
  CHECK(r != NULL);
  if (r) {
    unsigned char px[64];
    memset(&info, 0, sizeof info);
    CHECK(cloudsvc_shm_read_latest(r, 0, &info, px, 8) == -1); /* too small: info filled */
    CHECK(info.pixel_bytes == 32);
    memset(&info, 0, sizeof info);
    CHECK(cloudsvc_shm_read_latest(r, 0, &info, px, sizeof px) == 1);
    CHECK(info.frame_number == 7);
    CHECK(info.lat_deg == 47.5);
    CHECK(info.heading_deg == 271.0);
    CHECK(info.width == 4 && info.height == 2);
    CHECK(info.pixel_format == CLOUDSVC_SHM_RGBA8_SRGB);
    CHECK(info.row_bytes == 16);
    CHECK(info.publish_unix_ns == 1782043200123456789LL);
    int same = 1;
    for (int i = 0; i < 32; ++i) same = same && px[i] == (unsigned char)(i * 3);
    CHECK(same);
    CHECK(cloudsvc_shm_read_latest(r, 7, &info, px, sizeof px) == 0); /* nothing newer than 7 */
    CHECK(strcmp(cloudsvc_shm_last_error(r), "") == 0);
    /* A slot claiming more pixel bytes than its rows hold: -3 and a message, nothing copied. */
    s->pixel_bytes = 1u << 20;
    CHECK(cloudsvc_shm_read_latest(r, 0, &info, px, sizeof px) == -3);
    CHECK(strstr(cloudsvc_shm_last_error(r), "pixel_bytes") != NULL);
    cloudsvc_shm_close(r);
  }
  munmap(base, bytes);
  shm_unlink(path);
  if (failures == 0) printf("shm C ABI: all checks passed\n");
  return failures == 0 ? 0 : 1;
}
