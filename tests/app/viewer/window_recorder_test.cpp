#include "app/viewer/window_recorder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "../../io/temporary_folder.h"

namespace {

wobble::RgbaImage image_of(unsigned char red) {
  wobble::RgbaImage image;
  image.width = 4;
  image.height = 3;
  image.pixels.assign(4 * 3 * 4, 255);
  for (std::size_t i = 0; i < image.pixels.size(); i += 4)
    image.pixels[i] = red;
  return image;
}

TEST(WindowRecorder, EachRecordingGoesToANewFolderNumberedFromOne) {
  wobble::testing::TemporaryFolder folder;
  std::ostringstream progress;
  wobble::WindowRecorder recorder(folder.path().string(), progress);
  EXPECT_FALSE(recorder.active());
  EXPECT_EQ(recorder.status(), "");
  recorder.start("cloth");
  ASSERT_TRUE(recorder.active());
  for (unsigned char red : {10, 20, 30})
    recorder.write(image_of(red));
  const std::filesystem::path first = folder.path() / "wobble-cloth-frames-0001";
  EXPECT_EQ(recorder.status(), first.string() + "/ (3 frames)");
  EXPECT_EQ(recorder.stop(), "recorded 3 frames in " + first.string() + "/");
  EXPECT_FALSE(recorder.active());
  // The frames are the images written, in order.
  for (int frame = 1; frame <= 3; ++frame) {
    const std::string file = wobble::ImageOutputs::frame_file(first.string(), frame);
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    EXPECT_EQ(wobble::read_png(file).pixels[0], 10 * frame);
  }
  EXPECT_FALSE(std::filesystem::exists(wobble::ImageOutputs::frame_file(first.string(), 4)));
  // A second recording does not write into the first one's folder.
  recorder.start("cloth");
  recorder.write(image_of(40));
  recorder.stop();
  EXPECT_TRUE(std::filesystem::exists(
      wobble::ImageOutputs::frame_file((folder.path() / "wobble-cloth-frames-0002").string(), 1)));
}

TEST(WindowRecorder, AFolderThatCannotBeMadeIsRefusedBeforeAnyFrame) {
  std::ostringstream progress;
  wobble::WindowRecorder recorder("/nonexistent-wobble-folder/deeper", progress);
  EXPECT_ANY_THROW(recorder.start("cloth"));
}

}  // namespace
