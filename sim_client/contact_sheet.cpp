// Contact sheets with OpenImageIO (contact_sheet.h).
#include "sim_client/contact_sheet.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "sim_client/tone_map.h"

namespace cloudsvc::sim {

namespace {

constexpr float kBackground[3] = {0.08f, 0.08f, 0.08f};  // display values
constexpr float kLabelColour[3] = {1.0f, 0.9f, 0.3f};
// Fonts tried for the labels, by name (OpenImageIO searches the system font folders);
// "" is OpenImageIO's default, which Debian does not ship.
constexpr const char* kFonts[] = {"DejaVuSans", "FreeSans", "LiberationSans-Regular", ""};

OIIO::ImageBuf to_buffer(const DisplayImage& img) {
  OIIO::ImageBuf buf(OIIO::ImageSpec(img.width, img.height, 3, OIIO::TypeDesc::FLOAT));
  buf.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, img.rgb.data());
  return buf;
}

}  // namespace

std::vector<std::size_t> pick_evenly(std::size_t count, std::size_t n) {
  std::vector<std::size_t> out;
  if (count == 0 || n == 0) return out;
  if (count <= n) {
    for (std::size_t i = 0; i < count; ++i) out.push_back(i);
    return out;
  }
  if (n == 1) return {0};
  for (std::size_t k = 0; k < n; ++k) {
    // k * (count - 1) / (n - 1), rounded: first 0, last count - 1, strictly increasing
    // because count > n.
    out.push_back((k * (count - 1) * 2 + (n - 1)) / (2 * (n - 1)));
  }
  return out;
}

void write_contact_sheet(const std::vector<SheetFrame>& frames, const std::string& out_path) {
  if (frames.empty()) throw std::invalid_argument("contact sheet: no frames");
  const std::vector<std::size_t> pick = pick_evenly(frames.size(), kContactSheetMaxFrames);
  const int k = static_cast<int>(pick.size());
  const int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(k))));
  const int rows = (k + cols - 1) / cols;

  int tile_w = 0, tile_h = 0;
  std::vector<OIIO::ImageBuf> tiles;
  for (std::size_t idx : pick) {
    OIIO::ImageBuf img = to_buffer(read_display_image(frames[idx].path));
    if (tile_w == 0) {
      tile_w = std::min(img.spec().width, kContactSheetMaxTileWidth);
      tile_h = std::max(1, static_cast<int>(std::lround(static_cast<double>(img.spec().height) * tile_w / img.spec().width)));
    }
    if (img.spec().width != tile_w || img.spec().height != tile_h)
      img = OIIO::ImageBufAlgo::resize(img, "", 0.0f, OIIO::ROI(0, tile_w, 0, tile_h, 0, 1, 0, 3));
    tiles.push_back(std::move(img));
  }

  const int width = cols * tile_w + (cols + 1) * kContactSheetGap;
  const int height = rows * tile_h + (rows + 1) * kContactSheetGap;
  OIIO::ImageBuf sheet(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  OIIO::ImageBufAlgo::fill(sheet, kBackground);
  const int font_px = std::clamp(tile_h / 6, 8, 24);
  std::size_t font = 0;  // index into kFonts of the first font that draws
  for (int i = 0; i < k; ++i) {
    const int x = kContactSheetGap + (i % cols) * (tile_w + kContactSheetGap);
    const int y = kContactSheetGap + (i / cols) * (tile_h + kContactSheetGap);
    if (!OIIO::ImageBufAlgo::paste(sheet, x, y, 0, 0, tiles[static_cast<std::size_t>(i)]))
      throw std::runtime_error(out_path + ": cannot compose the contact sheet: " + sheet.geterror());
    // Optional label: needs a font OpenImageIO can find; a sheet without labels is still useful.
    std::string label = "#";
    label += std::to_string(frames[pick[static_cast<std::size_t>(i)]].frame_number);
    while (font < std::size(kFonts) &&
           !OIIO::ImageBufAlgo::render_text(sheet, x + 3, y + font_px + 1, label, font_px, kFonts[font], kLabelColour)) {
      (void)sheet.geterror();  // clear the error and try the next font; none left: no labels
      ++font;
    }
  }
  if (!sheet.write(out_path, OIIO::TypeDesc::UINT8))
    throw std::runtime_error(out_path + ": cannot write the contact sheet: " + sheet.geterror());
}

}  // namespace cloudsvc::sim
