// Display images from frame files (tone_map.h).
#include "sim_client/tone_map.h"

#include <OpenImageIO/imagebuf.h>

#include <algorithm>
#include <stdexcept>

#include "common/tone_map.h"

namespace cloudsvc::sim {

DisplayImage read_display_image(const std::string& path) {
  OIIO::ImageBuf buf(path);
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) throw std::runtime_error(path + ": cannot read image: " + buf.geterror());
  const OIIO::ImageSpec& spec = buf.spec();
  if (spec.nchannels < 3) throw std::runtime_error(path + ": need an RGB image");
  const OIIO::TypeDesc stored = buf.nativespec().format;  // the pixel type in the file
  std::vector<float> px(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  if (!buf.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, px.data()))
    throw std::runtime_error(path + ": cannot read pixels: " + buf.geterror());
  const bool linear = stored.basetype == OIIO::TypeDesc::HALF || stored.basetype == OIIO::TypeDesc::FLOAT ||
                      stored.basetype == OIIO::TypeDesc::DOUBLE;
  if (linear) px = tone_map_display(px, spec.nchannels);
  DisplayImage img;
  img.width = spec.width;
  img.height = spec.height;
  img.rgb.resize(static_cast<std::size_t>(img.width) * img.height * 3);
  for (std::size_t i = 0; i < img.rgb.size() / 3; ++i)
    for (int c = 0; c < 3; ++c)
      img.rgb[i * 3 + c] = std::clamp(px[i * spec.nchannels + c], 0.0f, 1.0f);
  return img;
}

void write_display_png(const std::string& path, const DisplayImage& img) {
  OIIO::ImageBuf buf(OIIO::ImageSpec(img.width, img.height, 3, OIIO::TypeDesc::FLOAT),
                     const_cast<float*>(img.rgb.data()));
  if (!buf.write(path, OIIO::TypeDesc::UINT8)) throw std::runtime_error(path + ": cannot write: " + buf.geterror());
}

}  // namespace cloudsvc::sim
