// Seed images for the weather-map fuzz target (seed_images.h).
#include "fuzz/seed_images.h"

#include <OpenImageIO/imagebuf.h>

#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace cloudsvc::fuzz {

namespace {

// A w x h image of nc channels with values in [0, 1] (a gradient), written as `type`.
void write_image(const std::filesystem::path& path, int w, int h, int nc, OIIO::TypeDesc type,
                 float special = 0.5f) {
  OIIO::ImageBuf buf(OIIO::ImageSpec(w, h, nc, OIIO::TypeDesc::FLOAT));
  std::vector<float> pixels(static_cast<std::size_t>(w) * h * nc);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<float>(i % 7) / 6.0f;
  pixels.back() = special;  // the last value: 0.5, or out of range / NaN for error seeds
  buf.set_pixels(buf.roi(), OIIO::TypeDesc::FLOAT, pixels.data());
  if (!buf.write(path.string(), type)) throw std::runtime_error(path.string() + ": " + buf.geterror());
}

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

// PFM (OIIO 2.4 reads it but does not write it): "Pf" (one channel), size, -1 (little
// endian), then the rows bottom to top as floats.
void write_pfm(const std::filesystem::path& path, int w, int h) {
  std::string bytes = "Pf\n" + std::to_string(w) + " " + std::to_string(h) + "\n-1.0\n";
  for (int i = 0; i < w * h; ++i) {
    const float v = static_cast<float>(i) / static_cast<float>(w * h);
    bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  write_bytes(path, bytes);
}

}  // namespace

void write_seed_images(const std::filesystem::path& dir) {
  using OIIO::TypeDesc;
  write_image(dir / "coverage-half.exr", 4, 3, 1, TypeDesc::HALF);
  write_image(dir / "rgba-float.exr", 5, 4, 4, TypeDesc::FLOAT);
  write_image(dir / "out-of-range.exr", 2, 2, 2, TypeDesc::FLOAT, 1.5f);
  write_image(dir / "nan.exr", 2, 2, 1, TypeDesc::FLOAT, std::numeric_limits<float>::quiet_NaN());
  write_image(dir / "gray8.png", 4, 3, 1, TypeDesc::UINT8);
  write_image(dir / "rgba16.png", 3, 3, 4, TypeDesc::UINT16);
  write_image(dir / "two-channel.tif", 4, 2, 2, TypeDesc::FLOAT);
  write_image(dir / "rgb.hdr", 3, 2, 3, TypeDesc::FLOAT);
  write_pfm(dir / "gray.pfm", 3, 2);
  write_image(dir / "gray-binary.pgm", 4, 3, 1, TypeDesc::UINT8);
  write_bytes(dir / "ascii.pgm", "P2\n# coverage\n3 2\n255\n0 128 255\n64 32 16\n");
}

}  // namespace cloudsvc::fuzz
