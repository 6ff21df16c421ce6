// Frame files (renderer/image_output.h) are written without following or clobbering
// anything planted in the output folder: the writer used to open a predictable temporary
// (".frame_000001.tmp<pid>.png") by name, so a symbolic link planted there by another
// local user made the service overwrite the link's target.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "renderer/image_output.h"

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

}  // namespace
}  // namespace cloudsvc
