/* C ABI of the shared-memory frame reader, for hosts written in C or other languages
 * (link libcloudsvc_shm.a and the C++ runtime). Layout and protocol: protocol/shm/shm_layout.h.
 *
 *   char err[256];
 *   cloudsvc_shm_reader* r = cloudsvc_shm_open("cloudsvc-frames", err, sizeof err);
 *   cloudsvc_shm_slot info;
 *   int rc = cloudsvc_shm_read_latest(r, last_frame, &info, buffer, buffer_bytes);
 *   if (rc == 1) { last_frame = info.frame_number; ... }
 *   if (rc == -3) fprintf(stderr, "%s\n", cloudsvc_shm_last_error(r));  // corrupt ring
 *   // delivery latency, ns: own CLOCK_REALTIME now - info.publish_unix_ns (same machine)
 *   cloudsvc_shm_close(r);
 */
#ifndef CLOUDSVC_PROTOCOL_SHM_CLOUDSVC_SHM_H
#define CLOUDSVC_PROTOCOL_SHM_CLOUDSVC_SHM_H

#include <stddef.h>
#include <stdint.h>

#include "protocol/shm/shm_layout.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cloudsvc_shm_reader cloudsvc_shm_reader;

/* Opens the ring "/name". On failure returns NULL and writes a message to error: also for
 * a segment whose header sizes do not fit the segment actually mapped (header_bytes,
 * slot_count x slot_stride, overflow-checked, max_width x max_height x 8, alignment). */
cloudsvc_shm_reader* cloudsvc_shm_open(const char* name, char* error, size_t error_size);

/* Copies the newest complete frame newer than after_frame. Returns 1 when a frame was
 * copied (info and pixels filled), 0 when there is no newer frame, -1 when capacity is
 * too small (info is filled so the caller can size the buffer), -2 on a bad argument, -3
 * when the ring is corrupt (latest_slot outside the ring, or a complete slot whose width,
 * height, pixel_format, row_bytes or pixel_bytes disagree with each other or the slot
 * size; nothing is copied, cloudsvc_shm_last_error says which). info.pixel_bytes is at
 * most the slot size and height x row_bytes with row_bytes >= width x bytes per pixel
 * (8 for RGBA16F, 4 for RGBA8) whenever 1 or -1 is returned. */
int cloudsvc_shm_read_latest(cloudsvc_shm_reader* reader, uint64_t after_frame, cloudsvc_shm_slot* info,
                             void* pixels, size_t capacity);

/* The message of the reader's last -3 from cloudsvc_shm_read_latest ("" if none); valid
 * until the next call on the reader. NULL reader: "". */
const char* cloudsvc_shm_last_error(const cloudsvc_shm_reader* reader);

void cloudsvc_shm_close(cloudsvc_shm_reader* reader);

#ifdef __cplusplus
}
#endif

#endif /* CLOUDSVC_PROTOCOL_SHM_CLOUDSVC_SHM_H */
