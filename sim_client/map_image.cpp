// Weather-map images (map_image.h).
#include "sim_client/map_image.h"

#include <OpenImageIO/imagebuf.h>

#include <cmath>

#include "sim_client/map_flags.h"
#include "sim_client/text_input.h"
#include "sim_client/usage_errors.h"

namespace cloudsvc::sim {

void check_map_values(const MapRaster& r, const std::string& source) {
  const std::size_t nc = r.channel_bits.size();
  for (std::size_t i = 0; i < r.values.size(); ++i) {
    const float v = r.values[i];
    if (std::isfinite(v) && v >= 0.0f && v <= 1.0f) continue;
    const std::size_t texel = i / nc, k = i % nc;
    const std::size_t x = texel % static_cast<std::size_t>(r.width), y = texel / static_cast<std::size_t>(r.width);
    throw UsageError(source + ": pixel (x " + std::to_string(x) + ", y " + std::to_string(y) + ") channel " +
                     std::to_string(k) + " (" + channel_name(r.channel_bits[k]) + "): value " + format_number(v) +
                     (std::isfinite(v) ? " outside [0, 1]" : " is not finite"));
  }
}

MapRaster read_map_image(const std::string& path, const std::vector<std::uint8_t>& channel_bits) {
  OIIO::ImageBuf buf(path);
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT))
    throw UsageError(path + ": cannot read image: " + buf.geterror());
  const OIIO::ImageSpec& spec = buf.spec();
  const int n = static_cast<int>(channel_bits.size());
  if (spec.nchannels < n)
    throw UsageError(path + ": image has " + std::to_string(spec.nchannels) + " channel(s) but --channels lists " +
                     std::to_string(n));
  MapRaster r;
  r.width = spec.width;
  r.height = spec.height;
  r.channel_bits = channel_bits;
  r.values.resize(static_cast<std::size_t>(r.width) * r.height * channel_bits.size());
  OIIO::ROI roi = buf.roi();
  roi.chbegin = 0;
  roi.chend = n;
  if (!buf.get_pixels(roi, OIIO::TypeDesc::FLOAT, r.values.data()))
    throw UsageError(path + ": cannot read pixels: " + buf.geterror());
  check_map_values(r, path);
  return r;
}

}  // namespace cloudsvc::sim
