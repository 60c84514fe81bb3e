#include "app/outputs/image_outputs.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "../../io/temporary_folder.h"
#include "sim/input_error.h"

namespace {

using wobble::ImageOutputs;

wobble::RgbaImage tiny(unsigned char value) {
  wobble::RgbaImage image;
  image.width = 2;
  image.height = 1;
  image.pixels = {value, value, value, 255, value, value, value, 255};
  return image;
}

TEST(ImageOutputs, FrameFilesAreNumberedFromOneWithFiveDigits) {
  EXPECT_EQ(ImageOutputs::frame_file("out", 1), "out/frame_00001.png");
  EXPECT_EQ(ImageOutputs::frame_file("out/", 123), "out/frame_00123.png");
  EXPECT_EQ(ImageOutputs::frame_file("o", 123456), "o/frame_123456.png");
}

TEST(ImageOutputs, ScreenshotMustBeAPngInAWritableFolder) {
  wobble::testing::TemporaryFolder folder;
  std::ostringstream progress;
  EXPECT_THROW(ImageOutputs(folder.file("a.jpg"), "", 1, progress), wobble::InputError);
  EXPECT_THROW(ImageOutputs(folder.file("missing/a.png"), "", 1, progress), wobble::InputError);
  EXPECT_NO_THROW(ImageOutputs(folder.file("A.PNG"), "", 1, progress));
  EXPECT_TRUE(folder.entries().empty()) << "checking writes nothing";
}

TEST(ImageOutputs, RecordCreatesItsFolderAtTheFirstFrameAndWritesEveryFrame) {
  wobble::testing::TemporaryFolder folder;
  std::ostringstream progress;
  const std::string record = folder.file("frames");
  ImageOutputs outputs(folder.file("last.png"), record, 250, progress);
  // Nothing until the first frame: input refused later must leave no empty folder.
  EXPECT_TRUE(folder.entries().empty());
  for (long frame = 1; frame <= 250; ++frame) {
    const bool last = frame == 250;
    ASSERT_TRUE(outputs.wants(last));
    outputs.write(frame, last, tiny(static_cast<unsigned char>(frame)), wobble::FrameTime());
  }
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(record),
                          std::filesystem::directory_iterator()),
            250);
  EXPECT_EQ(wobble::read_png(ImageOutputs::frame_file(record, 7)).pixels[0], 7);
  EXPECT_EQ(wobble::read_png(folder.file("last.png")).pixels[0], 250 % 256);
  // Progress: one line per hundred frames, and one at the end.
  EXPECT_EQ(progress.str(), "wobble: recorded 100 of 250 frames into " + record + "\n" +
                                "wobble: recorded 200 of 250 frames into " + record + "\n" +
                                "wobble: recorded 250 of 250 frames into " + record + "\n");
}

TEST(ImageOutputs, ScreenshotAloneWantsOnlyTheLastFrame) {
  wobble::testing::TemporaryFolder folder;
  std::ostringstream progress;
  const ImageOutputs outputs(folder.file("a.png"), "", 10, progress);
  EXPECT_FALSE(outputs.wants(false));
  EXPECT_TRUE(outputs.wants(true));
}

TEST(ImageOutputs, RecordIntoAFileOrUnderAMissingFolderIsRefused) {
  wobble::testing::TemporaryFolder folder;
  std::ostringstream progress;
  std::ofstream(folder.file("file")) << "x";
  EXPECT_THROW(ImageOutputs("", folder.file("file"), 1, progress), wobble::InputError);
  EXPECT_THROW(ImageOutputs("", folder.file("a/b"), 1, progress), wobble::InputError);
}

}  // namespace
