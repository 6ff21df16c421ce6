/* Shared-memory frame ring: the layout shared by the service (writer,
 * service/shm_frame_writer.*) and readers (sim_client/shm_frame_reader.*, C ABI in
 * sim_client/cloudsvc_shm.h). C-compatible, little-endian, fixed-size fields.
 * Documented in docs/PROTOCOL.md ("Shared-memory frames").
 *
 * Segment (POSIX shm, name "/<name>"):
 *   offset 0:                 cloudsvc_shm_header (padded to CLOUDSVC_SHM_HEADER_BYTES)
 *   offset header_bytes + i * slot_stride, i < slot_count:
 *                             cloudsvc_shm_slot (padded to CLOUDSVC_SHM_SLOT_HEADER_BYTES)
 *                             followed by the pixels: height rows of row_bytes, top row first
 *
 * Consistency: every slot is a seqlock. The writer makes `seq` odd, writes the slot,
 * then makes `seq` even (release). A reader copies the slot between two acquire loads of
 * `seq` and keeps the copy only if both are equal and even: it never returns a torn
 * frame and never blocks the writer (a reader that dies holds nothing). The writer fills
 * slots round-robin and then publishes `latest_slot` / `latest_frame`.
 *
 * Versions: 2 added cloudsvc_shm_slot.publish_unix_ns (version 1 readers refuse a version
 * 2 ring and vice versa: the reader checks `version`).
 */
#ifndef CLOUDSVC_PROTOCOL_SHM_LAYOUT_H
#define CLOUDSVC_PROTOCOL_SHM_LAYOUT_H

#include <stdint.h>

#define CLOUDSVC_SHM_MAGIC 0x4D485343u /* "CSHM" little-endian */
#define CLOUDSVC_SHM_VERSION 2u
#define CLOUDSVC_SHM_HEADER_BYTES 4096u
#define CLOUDSVC_SHM_SLOT_HEADER_BYTES 256u

/* Pixel formats of a slot. */
#define CLOUDSVC_SHM_RGBA16F_LINEAR 0u /* 4 x IEEE half, linear radiance, A = cloud opacity */
#define CLOUDSVC_SHM_RGBA8_SRGB 1u     /* 4 x uint8, tone-mapped, sRGB transfer, A = 255 */

typedef struct cloudsvc_shm_header {
  uint32_t magic;          /* CLOUDSVC_SHM_MAGIC */
  uint32_t version;        /* CLOUDSVC_SHM_VERSION */
  uint32_t header_bytes;   /* offset of slot 0 */
  uint32_t slot_count;     /* number of slots in the ring */
  uint64_t slot_stride;    /* bytes from one slot to the next (slot header + max pixels) */
  uint32_t max_width;      /* largest frame the slots can hold, pixels */
  uint32_t max_height;
  uint32_t writer_pid;     /* process id of the service */
  uint32_t reserved0;
  uint64_t latest_frame;   /* atomic: frame number of the newest complete frame, 0 = none */
  uint32_t latest_slot;    /* atomic: slot holding latest_frame */
  uint32_t reserved1;
} cloudsvc_shm_header;

typedef struct cloudsvc_shm_slot {
  uint64_t seq;            /* atomic seqlock counter: odd while the slot is being written */
  uint64_t frame_number;   /* service frame counter, starts at 1 */
  double sim_time_s;       /* pose echo: host simulation time, s */
  double unix_time_s;      /* UTC time the frame was rendered for, s since 1970 */
  double lat_deg;          /* pose echo: WGS84 latitude, degrees */
  double lon_deg;          /* longitude, degrees */
  double alt_m;            /* height above the ellipsoid, m */
  double heading_deg;      /* true heading, degrees */
  double pitch_deg;        /* degrees, nose up positive */
  double roll_deg;         /* degrees, right wing down positive */
  double render_ms;        /* GPU render + readback time, ms */
  uint32_t width;          /* pixels */
  uint32_t height;
  uint32_t pixel_format;   /* CLOUDSVC_SHM_* */
  uint32_t row_bytes;      /* bytes per row (width * 8 or width * 4) */
  uint64_t pixel_bytes;    /* height * row_bytes */
  int64_t publish_unix_ns; /* CLOCK_REALTIME when the writer published the slot (just before
                              `seq` became even), ns since 1970-01-01T00:00:00Z; a reader on the
                              same machine gets its delivery latency as its own CLOCK_REALTIME
                              minus this (version 2) */
} cloudsvc_shm_slot;

#ifdef __cplusplus
static_assert(sizeof(cloudsvc_shm_header) <= CLOUDSVC_SHM_HEADER_BYTES, "shm header");
static_assert(sizeof(cloudsvc_shm_slot) <= CLOUDSVC_SHM_SLOT_HEADER_BYTES, "shm slot header");
#endif

#endif /* CLOUDSVC_PROTOCOL_SHM_LAYOUT_H */
