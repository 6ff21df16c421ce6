/* Shared-memory frame ring: the module protocol/shm/ (CMake target cloudsvc_shm, GL-free,
 * POSIX only) and the ring's binary layout, shared by the writer (the service) and every
 * reader (sim_client, the C ABI for hosts). C-compatible, little-endian, fixed-size
 * fields. Documented in docs/PROTOCOL.md ("Shared-memory frames").
 *
 * Files of the module:
 *   shm_layout.h           this layout (C and C++)
 *   shm_name.h             the rule for ring names (NAME of "/NAME")
 *   shm_frame_writer.*     ShmFrameWriter: creates the segment, publishes frames (service)
 *   shm_ring_geometry.*    overflow-checked validation of the sizes a ring declares
 *   shm_frame_reader.*     ShmFrameReader: maps a ring read-only, copies the newest frame
 *   cloudsvc_shm.h         C ABI of the reader (cloudsvc_shm_c.cpp), for C hosts
 *
 * Segment (POSIX shm, name "/<name>", created by the writer with permissions it is given,
 * owner-only by default; removed by the writer when it stops):
 *   offset 0:                 cloudsvc_shm_header (padded to CLOUDSVC_SHM_HEADER_BYTES)
 *   offset header_bytes + i * slot_stride, i < slot_count:
 *                             cloudsvc_shm_slot (padded to CLOUDSVC_SHM_SLOT_HEADER_BYTES)
 *                             followed by the pixels: height rows of row_bytes, top row first
 * The writer sizes every slot for its largest frame in the larger format (RGBA16F):
 * slot_stride = 256 + (max_width x max_height x 8 bytes rounded up to a multiple of 4096).
 *
 * Opening (writer): a segment of that name whose header names a live writer_pid is refused
 * (another service owns it); a stale one (its writer is dead) is unlinked and replaced. The
 * writer fills the header and stores `magic` last (release): a reader that sees the magic
 * sees the whole header.
 *
 * Publishing one frame (writer), slots used round-robin, never waiting for a reader:
 *   1. seq = seq + 1 (odd: being written), then a release fence;
 *   2. write the slot header (frame number, pose echo, size, format) and the pixels;
 *   3. publish_unix_ns = CLOCK_REALTIME now;
 *   4. seq = seq + 1 (even: complete), release store;
 *   5. latest_slot = the slot, then latest_frame = its frame number (release stores).
 *
 * Reading the newest frame (reader), lock-free: every slot is a seqlock.
 *   1. acquire latest_frame; nothing newer than the caller's last frame: done;
 *   2. acquire latest_slot (must be < slot_count), then the slot's seq s1; odd: retry;
 *   3. copy the slot header and, if its sizes agree with the ring, the pixels;
 *   4. acquire fence, reload seq; different from s1: the writer lapped the reader, retry.
 * A copy is kept only when seq was even and unchanged around it: a reader never returns a
 * torn frame and never blocks the writer (a reader that dies holds nothing). A reader trusts
 * none of the sizes in the segment: the header's sizes are checked once against the mapped
 * segment (shm_ring_geometry.h) and every complete slot header against the ring before its
 * pixels are copied; a disagreement is reported as a corrupt ring, never read through.
 *
 * Versions: 2 added cloudsvc_shm_slot.publish_unix_ns (version 1 readers refuse a version
 * 2 ring and vice versa: the reader checks `version`).
 */
#ifndef CLOUDSVC_PROTOCOL_SHM_SHM_LAYOUT_H
#define CLOUDSVC_PROTOCOL_SHM_SHM_LAYOUT_H

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

#endif /* CLOUDSVC_PROTOCOL_SHM_SHM_LAYOUT_H */
