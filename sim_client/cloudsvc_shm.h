/* C ABI of the shared-memory frame reader, for hosts written in C or other languages
 * (link libcloudsvc_sim_client.a and the C++ runtime). Layout: protocol/shm_layout.h.
 *
 *   char err[256];
 *   cloudsvc_shm_reader* r = cloudsvc_shm_open("cloudsvc-frames", err, sizeof err);
 *   cloudsvc_shm_slot info;
 *   int rc = cloudsvc_shm_read_latest(r, last_frame, &info, buffer, buffer_bytes);
 *   if (rc == 1) { last_frame = info.frame_number; ... }
 *   // delivery latency, ns: own CLOCK_REALTIME now - info.publish_unix_ns (same machine)
 *   cloudsvc_shm_close(r);
 */
#ifndef CLOUDSVC_SIM_CLIENT_CLOUDSVC_SHM_H
#define CLOUDSVC_SIM_CLIENT_CLOUDSVC_SHM_H

#include <stddef.h>
#include <stdint.h>

#include "protocol/shm_layout.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cloudsvc_shm_reader cloudsvc_shm_reader;

/* Opens the ring "/name". On failure returns NULL and writes a message to error. */
cloudsvc_shm_reader* cloudsvc_shm_open(const char* name, char* error, size_t error_size);

/* Copies the newest complete frame newer than after_frame. Returns 1 when a frame was
 * copied (info and pixels filled), 0 when there is no newer frame, -1 when capacity is
 * too small (info is filled so the caller can size the buffer), -2 on a bad argument. */
int cloudsvc_shm_read_latest(cloudsvc_shm_reader* reader, uint64_t after_frame, cloudsvc_shm_slot* info,
                             void* pixels, size_t capacity);

void cloudsvc_shm_close(cloudsvc_shm_reader* reader);

#ifdef __cplusplus
}
#endif

#endif /* CLOUDSVC_SIM_CLIENT_CLOUDSVC_SHM_H */
