#include "service/frame_sinks.h"

#include <cstdio>
#include <stdexcept>

#include "renderer/image_output.h"
#include "service/frame_encoding.h"
#include "service/output_directory.h"

namespace cloudsvc {

ShmFrameMeta shm_frame_meta(std::uint64_t frame, const protocol::Pose& pose, double utc_s, const FrameImage& img) {
  return shm_frame_meta(frame, pose.sim_time_s, utc_s, {pose.lat_deg, pose.lon_deg, pose.alt_m},
                        {pose.heading_deg, pose.pitch_deg, pose.roll_deg}, img);
}

ShmFrameMeta shm_frame_meta(std::uint64_t frame, double sim_time_s, double utc_s, const geo::Geodetic& position,
                            const geo::Attitude& attitude, const FrameImage& img) {
  return ShmFrameMeta{frame,
                      sim_time_s,           utc_s,
                      position.lat_deg,     position.lon_deg,   position.alt_m,
                      attitude.heading_deg, attitude.pitch_deg, attitude.roll_deg,
                      img.stats.render_ms};
}

std::uint32_t publish_to_shm(ShmFrameWriter& shm, const FrameImage& img, const ShmFrameMeta& meta,
                             protocol::ShmPixelFormat format) {
  if (format == protocol::ShmPixelFormat::Rgba8Srgb) {
    const auto px = to_rgba8_srgb(img);
    return shm.write(meta, CLOUDSVC_SHM_RGBA8_SRGB, img.width, img.height, px.data(),
                     static_cast<std::size_t>(img.width) * 4);
  }
  const auto px = to_rgba16f(img);
  return shm.write(meta, CLOUDSVC_SHM_RGBA16F_LINEAR, img.width, img.height, px.data(),
                   static_cast<std::size_t>(img.width) * 8);
}

std::string publish_to_file(const FrameImage& img, std::uint64_t frame, const protocol::SetView& view,
                            const std::string& root) {
  const ClientDirectory dir = resolve_client_directory(view.file_dir, root);
  if (!dir.problem.empty()) throw std::runtime_error(dir.problem);
  char name[64];
  std::snprintf(name, sizeof name, "frame_%06llu.%s", static_cast<unsigned long long>(frame),
                view.file_format == protocol::FileFormat::Exr ? "exr" : "png");
  const std::string path = (dir.path / name).string();
  write_image(path, img);
  return path;
}

}  // namespace cloudsvc
