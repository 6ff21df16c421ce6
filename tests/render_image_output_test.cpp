// Frame files (renderer/image_output.h) are written without following or clobbering
// anything planted in the output folder: the writer used to open a predictable temporary
// (".frame_000001.tmp<pid>.png") by name, so a symbolic link planted there by another
// local user made the service overwrite the link's target. The PNG frames are tone mapped
// as sim_client converts the EXR frames (common/tone_map.h).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include "renderer/image_output.h"
#include "sim_client/tone_map.h"

namespace cloudsvc {
namespace {

namespace fs = std::filesystem;

FrameImage small_frame() {
  FrameImage img;
  img.width = 8;
  img.height = 4;
  img.rgba.assign(static_cast<std::size_t>(img.width) * img.height * 4, 0.05f);
  return img;
}

std::string contents(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

class ImageOutputSafety : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cloudsvc_image_output_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "out");
    victim_ = dir_ / "victim.txt";
    std::ofstream(victim_) << "precious";
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_, victim_;
};

TEST_F(ImageOutputSafety, LinksPlantedAtTemporaryNamesAreNotFollowed) {
  for (const char* ext : {"png", "exr"}) {
    SCOPED_TRACE(ext);
    const fs::path out = dir_ / "out" / (std::string("frame_000001.") + ext);
    // Every temporary name the old writer could have used in this process.
    fs::create_symlink(victim_, dir_ / "out" / (".frame_000001.tmp" + std::to_string(::getpid()) + "." + ext));
    write_image(out.string(), small_frame());
    EXPECT_EQ(contents(victim_), "precious") << "the planted link's target was overwritten";
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(out)));
    EXPECT_GT(fs::file_size(out), 0u);
  }
}

TEST_F(ImageOutputSafety, ALinkAtTheFinalNameIsReplacedNotWrittenThrough) {
  const fs::path out = dir_ / "out" / "frame_000002.png";
  fs::create_symlink(victim_, out);
  write_image(out.string(), small_frame());
  EXPECT_EQ(contents(victim_), "precious");
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(out))) << "the link itself is replaced by the frame";
}

TEST_F(ImageOutputSafety, NoTemporaryIsLeftAndTheFrameIsReadableByOthers) {
  const fs::path out = dir_ / "out" / "frame_000003.exr";
  write_image(out.string(), small_frame());
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "out")) {
    ++files;
    EXPECT_EQ(e.path(), out) << "left behind: " << e.path();
  }
  EXPECT_EQ(files, 1u);
  struct stat st {};
  ASSERT_EQ(::stat(out.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
  EXPECT_THROW(write_image((dir_ / "missing" / "f.png").string(), small_frame()), std::runtime_error);
}

// EXR frames keep the radiance of a night (the night sky, 2e-9 W m^-2 sr^-1 nm^-1, and
// twilight values of 1e-6) as written: half floats made the first 0 and kept 1-6 % of the
// second; 32-bit floats are exact.
TEST_F(ImageOutputSafety, ExrKeepsNightRadiance) {
  FrameImage img;
  img.width = 4;
  img.height = 1;
  img.rgba = {2.0e-9f, 3.3e-9f, 7.1e-9f, 0.0f, 1.234e-6f, 2.345e-6f, 9.876e-6f, 0.5f,
              0.05f, 0.06f, 0.07f, 1.0f, 123.4f, 234.5f, 345.6f, 0.25f};
  img.std_error = {1e-10f, 2e-10f, 3e-10f, 1e-7f, 2e-7f, 3e-7f, 1e-3f, 2e-3f, 3e-3f, 1.0f, 2.0f, 3.0f};
  const fs::path exr = dir_ / "out" / "night.exr";
  write_image(exr.string(), img);
  auto in = OIIO::ImageInput::open(exr.string());
  ASSERT_TRUE(in);
  ASSERT_EQ(in->spec().nchannels, 7);
  std::vector<float> px(4 * 7);
  ASSERT_TRUE(in->read_image(0, 0, 0, 7, OIIO::TypeDesc::FLOAT, px.data()));
  for (int i = 0; i < 4; ++i) {
    for (int c = 0; c < 4; ++c) EXPECT_EQ(px[i * 7 + c], img.rgba[i * 4 + c]) << "pixel " << i << " channel " << c;
    for (int c = 0; c < 3; ++c) EXPECT_EQ(px[i * 7 + 4 + c], img.std_error[i * 3 + c]) << "pixel " << i << " se " << c;
  }
}

// The service's PNG of a frame and sim_client's display conversion of the same frame
// written as EXR (sweep --png, contact sheets) agree to 1 step of 255; non-finite and
// negative radiance is black in both.
TEST_F(ImageOutputSafety, ServicePngAndSimClientConversionOfTheExrAgree) {
  FrameImage img;
  img.width = 32;
  img.height = 8;
  for (int i = 0; i < img.width * img.height; ++i) {
    const float r = 1e-3f * std::pow(1.05f, static_cast<float>(i));  // 1e-3 .. 250 W m^-2 sr^-1 nm^-1
    for (float v : {r, 0.8f * r, 1.2f * r, 0.5f}) img.rgba.push_back(v);
  }
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const float bad[] = {nan, inf, -inf, -1.0f};
  for (int i = 0; i < 4; ++i) img.rgba[i * 4 * 7] = img.rgba[i * 4 * 7 + 1] = img.rgba[i * 4 * 7 + 2] = bad[i];
  const fs::path png = dir_ / "out" / "frame.png", exr = dir_ / "out" / "frame.exr";
  write_image(png.string(), img);
  write_image(exr.string(), img);
  const sim::DisplayImage service = sim::read_display_image(png.string());  // 8-bit: as stored
  const sim::DisplayImage client = sim::read_display_image(exr.string());   // tone mapped
  ASSERT_EQ(service.rgb.size(), client.rgb.size());
  ASSERT_EQ(service.rgb.size(), static_cast<std::size_t>(img.width) * img.height * 3);
  int worst = 0;
  for (std::size_t k = 0; k < service.rgb.size(); ++k) {
    const long a = std::lround(service.rgb[k] * 255.0f), b = std::lround(client.rgb[k] * 255.0f);
    worst = std::max(worst, static_cast<int>(std::labs(a - b)));
  }
  EXPECT_LE(worst, 1);
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(service.rgb[i * 3 * 7 + c], 0.0f) << "bad pixel " << i;
      EXPECT_EQ(client.rgb[i * 3 * 7 + c], 0.0f) << "bad pixel " << i;
    }
  EXPECT_EQ(std::lround(service.rgb.back() * 255.0f), 255) << "the brightest pixel saturates";
}

}  // namespace
}  // namespace cloudsvc
