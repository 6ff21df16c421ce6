// Fuzz target: weather-map images to protocol tiles, as `sim_client weather --map IMAGE
// --channels ... --bounds ...` does: sim::read_map_image() (sim_client/map_image.h, through
// OpenImageIO) then sim::split_into_tiles() (sim_client/map_tiles.h).
// read_map_image() takes a path, so each input is written to a temporary file of this
// process (mkstemps, one per file suffix). The suffix comes from the input's magic bytes
// (PNG, OpenEXR, TIFF, Radiance HDR, PNM/PFM; anything else is named .exr), and OpenImageIO
// is told not to try its other readers (attribute try_all_readers 0), so every input goes
// to the reader its content claims rather than to all thirty of OIIO's formats.
// OpenImageIO's shared ImageCache, which ImageBuf reads through, remembers a file by name:
// the target drops that entry before every read, or the cache would describe the previous
// input (sim_client reads a file once). Memory bounds of this target, not of sim_client:
// images whose header claims over 64 MB of pixels are skipped (claims_over_64_mb), and so
// are OpenEXR headers that make OpenEXR allocate far more than the file holds
// (exr_header_overallocates). The channel list (--channels) and the bounds
// (--bounds, one crossing the antimeridian) are chosen by the input's length. Leak checks
// are off for this target (__asan_default_options below says why).
// Invariants checked besides the sanitizers':
//  - only UsageError is thrown (exit code 2 in sim_client), with a message that starts
//    with the file's path;
//  - a raster read has the listed channels and width x height texels of finite values in
//    [0, 1];
//  - its tiles (at the side allowed by the protocol's limits, or 3 texels to make many)
//    cover every texel once, and each is a WeatherMapTile that protocol::validate()
//    accepts and that converts to a weather::MapTile without problem().
#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/imageio.h>
#include <stdlib.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "protocol/messages.h"
#include "protocol/validate.h"
#include "protocol/weather_conversion.h"
#include "sim_client/map_flags.h"
#include "sim_client/map_image.h"
#include "sim_client/map_tiles.h"
#include "sim_client/usage_errors.h"

namespace {

using namespace cloudsvc;
namespace ch = protocol::tile_channel;

// True for OpenEXR headers that make OpenEXR 3.1 allocate far more than the file holds,
// before it checks anything: an attribute declared longer than the bytes that follow it
// (its declared size, up to 2 GiB, is allocated first: Imf::TypedAttribute::readValueFrom,
// Imf::OpaqueAttribute), or a data window over 65536 pixels or with an empty side (line
// buffers and compressors are sized from it: Imf::newCompressor). A 32-byte file makes every
// OpenImageIO reader, sim_client included, allocate 1.8 GB, a 200-byte one 8 GB, and then
// fail. That is the library's behaviour, not this project's; at seconds per input and
// beyond libFuzzer's memory limit it would stop the target, so such inputs are skipped.
// Header layout: magic, 4-byte version, then per attribute "name\0type\0", a
// little-endian int32 size and the value; an empty name ends a header (multi-part files,
// version bit 12, have several, ended by an empty header).
bool exr_header_overallocates(std::string_view d) {
  if (d.size() < 8 || d.substr(0, 4) != std::string_view("\x76\x2f\x31\x01", 4)) return false;
  const bool multipart = (static_cast<unsigned char>(d[5]) & 0x10) != 0;
  std::size_t i = 8;
  while (i < d.size()) {
    if (d[i] == '\0') {  // end of a header
      if (!multipart || i + 1 >= d.size() || d[i + 1] == '\0') return false;
      ++i;
      continue;
    }
    const std::size_t name_end = d.find('\0', i);
    const std::size_t type_end = name_end == std::string_view::npos ? name_end : d.find('\0', name_end + 1);
    if (type_end == std::string_view::npos || d.size() - type_end < 5) return false;  // truncated: fails anyway
    const std::string_view name = d.substr(i, name_end - i);
    std::uint32_t size = 0;
    std::memcpy(&size, d.data() + type_end + 1, 4);
    i = type_end + 5;
    if (size > d.size() - i) return true;  // also every negative int32
    if (name == "dataWindow" && size == 16) {
      std::int32_t box[4];  // xmin, ymin, xmax, ymax
      std::memcpy(box, d.data() + i, sizeof box);
      const std::int64_t w = std::int64_t{box[2]} - box[0] + 1, h = std::int64_t{box[3]} - box[1] + 1;
      if (w < 1 || h < 1 || w * h > 65536) return true;
    }
    i += size;
  }
  return false;
}

// True when the image's header claims more than 64 MB of pixels. ImageBuf::read allocates
// the claimed size before it reads a pixel, and OIIO 2.4's readers do not all honour its
// limits:imagesize_MB (the PNM/PFM reader does not): a 70-byte PFM claiming 2^31 x 1 pixels
// makes it allocate 8 GB, harmless with the overcommitting malloc sim_client runs with
// (the read fails before touching it), an out-of-memory report under AddressSanitizer.
// Read through ImageInput, which only parses the header.
bool claims_over_64_mb(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    OIIO::geterror();  // read_map_image reports the failure; do not let errors pile up
    return false;
  }
  return in->spec().image_bytes() > (std::uint64_t{64} << 20);
}

// The file suffix OpenImageIO should read the input as.
std::string suffix_for(std::string_view d) {
  if (d.substr(0, 4) == "\x89PNG") return ".png";
  if (d.substr(0, 4) == std::string_view("\x76\x2f\x31\x01", 4)) return ".exr";
  if (d.substr(0, 4) == std::string_view("II*\0", 4) || d.substr(0, 4) == std::string_view("MM\0*", 4)) return ".tif";
  if (d.substr(0, 2) == "#?") return ".hdr";
  if (d.size() >= 2 && d[0] == 'P' && (d[1] == 'F' || d[1] == 'f')) return ".pfm";
  if (d.size() >= 2 && d[0] == 'P' && d[1] >= '1' && d[1] <= '6') return ".pnm";
  return ".exr";
}

// Temporary files of this process, one per suffix, removed at exit.
struct TempFiles {
  std::map<std::string, std::pair<int, std::string>> files;  // suffix -> (fd, path)

  ~TempFiles() {
    for (const auto& [suffix, file] : files) {
      ::close(file.first);
      ::unlink(file.second.c_str());
    }
  }

  const std::string& write(const std::string& suffix, const std::uint8_t* data, std::size_t size) {
    auto it = files.find(suffix);
    if (it == files.end()) {
      const char* dir = std::getenv("TMPDIR");
      std::string name = std::string(dir && *dir ? dir : "/tmp") + "/cloudsvc-fuzz-map-XXXXXX" + suffix;
      const int fd = ::mkstemps(name.data(), static_cast<int>(suffix.size()));
      if (fd < 0) {
        std::perror("mkstemps");
        std::abort();
      }
      it = files.emplace(suffix, std::make_pair(fd, name)).first;
    }
    const int fd = it->second.first;
    if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, data, size, 0) != static_cast<ssize_t>(size)) {
      std::perror("writing the fuzz input");
      std::abort();
    }
    return it->second.second;
  }
};

const std::array<std::vector<std::uint8_t>, 6> kChannelLists = {{
    {ch::kCoverage},
    {ch::kCoverage, ch::kVerticalDevelopment, ch::kDensity, ch::kPrecipitation},
    {ch::kDensity, ch::kCoverage},
    {ch::kPrecipitation},
    {ch::kCoverage, ch::kDensity},
    {ch::kVerticalDevelopment, ch::kPrecipitation, ch::kCoverage},
}};

const std::array<sim::GeoBounds, 2> kBounds = {{{40.0, 0.0, 50.0, 20.0}, {-10.0, 170.0, 10.0, 190.0}}};

void check_tiles(const sim::MapRaster& raster, const sim::GeoBounds& bounds, std::uint32_t side) {
  const auto tiles = sim::split_into_tiles(raster, bounds, 1782043200.0, side);
  std::uint64_t texels = 0;
  for (const protocol::WeatherMapTile& t : tiles) {
    texels += std::uint64_t{t.width} * t.height;
    if (const auto problem = protocol::validate(protocol::Message(t))) {
      std::fprintf(stderr, "validate: %s\n", problem->c_str());
      FUZZ_CHECK(false, "sim_client would send a tile the service refuses");
    }
    FUZZ_CHECK(to_map_tile(t).problem().empty(), "a tile has a MapTile::problem()");
  }
  FUZZ_CHECK(texels == std::uint64_t(raster.width) * raster.height, "tiles do not cover every texel once");
}

}  // namespace

// No leak checks: OpenImageIO 2.4's PNG reader leaks the std::string of an error message
// whenever libpng longjmps out of a read error (PNGInput::PngReadCallback), and
// LeakSanitizer can tell that frame apart only with full malloc unwinding
// (fast_unwind_on_malloc=0), which halves this target's speed. The project's part of this
// path (read_map_image, split_into_tiles) keeps its memory in std::vector only, and the
// sanitizer build's sim_client tests check it for leaks with valid images.
extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  OIIO::attribute("threads", 1);
  OIIO::attribute("try_all_readers", 0);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static TempFiles temp;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  if (exr_header_overallocates(bytes)) return 0;
  const std::string& path = temp.write(suffix_for(bytes), data, size);
  const std::vector<std::uint8_t>& bits = kChannelLists[size % kChannelLists.size()];
  const sim::GeoBounds& bounds = kBounds[size / kChannelLists.size() % kBounds.size()];

  if (claims_over_64_mb(path)) return 0;
  OIIO::ImageCache::create(/*shared=*/true)->invalidate(OIIO::ustring(path), /*force=*/true);
  sim::MapRaster raster;
  try {
    raster = sim::read_map_image(path, bits);
  } catch (const sim::UsageError& e) {
    // OpenImageIO's error texts may span lines; sim_client's main() prints every error
    // on one line, so only the start is checked here.
    FUZZ_CHECK(std::string_view(e.what()).starts_with(path + ": "), "a weather-map error does not start with the path");
    return 0;
  }
  FUZZ_CHECK(raster.channel_bits == bits, "the raster's channels are not the ones listed");
  FUZZ_CHECK(raster.width >= 1 && raster.height >= 1, "an empty raster was returned");
  FUZZ_CHECK(raster.values.size() == std::size_t(raster.width) * raster.height * bits.size(),
             "the raster's value count does not match its size");
  for (const float v : raster.values) FUZZ_CHECK(v >= 0.0f && v <= 1.0f, "a map value outside [0, 1] or NaN");

  check_tiles(raster, bounds, sim::tile_side_for(protocol::protocol_limits(), static_cast<int>(bits.size())));
  if (std::uint64_t(raster.width) * raster.height <= 4096) check_tiles(raster, bounds, 3);
  return 0;
}
