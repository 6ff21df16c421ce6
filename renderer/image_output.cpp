#include "renderer/image_output.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace cloudsvc {

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// The encoded file (EXR or PNG) in memory: OpenImageIO writes through an in-memory proxy,
// so no file is opened by name until write_file_safely.
std::vector<unsigned char> encode_image(const std::string& path, const std::string& ext, const FrameImage& img,
                                        double exposure_ev) {
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput proxy(bytes);
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error(path + ": cannot create image writer: " + OIIO::geterror());
  if (!out->supports("ioproxy")) throw std::runtime_error(path + ": the image writer cannot write to memory");
  bool ok = false;
  if (ext == ".exr") {
    // A Monte Carlo image (the path-traced truth) adds its standard error as se.R/G/B.
    const bool with_error = img.std_error.size() == img.rgba.size() / 4 * 3 && !img.std_error.empty();
    const int channels = with_error ? 7 : 4;
    // 32-bit float: a night sky (~2e-9) is below half float's smallest value and twilight radiance
    // (1e-6) has a few bits in it
    OIIO::ImageSpec spec(img.width, img.height, channels, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"R", "G", "B", "A"};
    spec.attribute("compression", "zip");
    spec.attribute("cloudsvc:radiance_units", "W m^-2 sr^-1 nm^-1 at 680/550/440 nm; A = cloud opacity");
    std::vector<float> pixels;
    const float* data = img.rgba.data();
    if (with_error) {
      spec.channelnames.insert(spec.channelnames.end(), {"se.R", "se.G", "se.B"});
      spec.attribute("cloudsvc:std_error", "se.R/G/B = standard error of the mean radiance of R/G/B, same units");
      const std::size_t n = img.rgba.size() / 4;
      pixels.resize(n * 7);
      for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 4; ++c) pixels[i * 7 + c] = img.rgba[i * 4 + c];
        for (int c = 0; c < 3; ++c) pixels[i * 7 + 4 + c] = img.std_error[i * 3 + c];
      }
      data = pixels.data();
    }
    OIIO::Filesystem::IOProxy* p = &proxy;
    spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &p);
    ok = out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, data);
  } else {
    const std::vector<std::uint8_t> px = tone_map_srgb8(img.rgba, 4, exposure_ev);  // FrameImage: RGBA
    OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::UINT8);
    OIIO::Filesystem::IOProxy* p = &proxy;
    spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &p);
    ok = out->open(path, spec) && out->write_image(OIIO::TypeDesc::UINT8, px.data());
  }
  ok = out->close() && ok;
  if (!ok) throw std::runtime_error(path + ": encoding failed: " + out->geterror());
  return bytes;
}

// Writes bytes to path without following or clobbering anything an attacker may have put
// in the folder: a fresh temporary with an unpredictable name is created exclusively
// (mkostemps: O_CREAT | O_EXCL, which never follows a symbolic link), filled, synced and
// renamed over path (rename replaces a link at path, never the file it points to).
void write_file_safely(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  const std::string ext = path.extension().string();
  std::string tmpl = (path.parent_path() / ("." + path.stem().string() + ".XXXXXX" + ext)).string();
  const int fd = ::mkostemps(tmpl.data(), static_cast<int>(ext.size()), O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(path.string() + ": cannot create a temporary file: " + std::strerror(errno));
  bool ok = ::fchmod(fd, 0644) == 0;  // mkostemps makes 0600; a frame is for other readers too
  for (std::size_t done = 0; ok && done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    ok = n > 0;
    if (ok) done += static_cast<std::size_t>(n);
  }
  const int write_errno = errno;
  ok = ::close(fd) == 0 && ok;
  if (!ok || ::rename(tmpl.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(ok ? errno : write_errno);
    ::unlink(tmpl.c_str());
    throw std::runtime_error(path.string() + ": write failed: " + why);
  }
}

}  // namespace

void write_image(const std::string& path, const FrameImage& img, double exposure_ev) {
  const std::string ext = lower_extension(path);
  if (ext != ".exr" && ext != ".png") throw std::runtime_error(path + ": unsupported extension (use .exr or .png)");
  write_file_safely(std::filesystem::path(path), encode_image(path, ext, img, exposure_ev));
}

}  // namespace cloudsvc
