#include "io/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "sim/input_error.h"
#include "temporary_folder.h"

namespace {

using wobble::FileKind;

constexpr FileKind small_text{"a test file", 100};

// The message read_input_file throws for `path`, or "" when it reads the file.
std::string error_reading(const std::string& path, const FileKind& kind = small_text) {
  try {
    wobble::read_input_file(path, kind);
  } catch (const wobble::InputError& error) {
    return error.what();
  }
  return "";
}

TEST(InputFile, ReadsARegularFileWhole) {
  wobble::testing::TemporaryFolder folder;
  std::ofstream(folder.file("a.txt"), std::ios::binary) << std::string("one\ntwo\0three", 13);
  EXPECT_EQ(wobble::read_input_file(folder.file("a.txt"), small_text),
            std::string("one\ntwo\0three", 13));
  EXPECT_EQ(wobble::input_file_problem(folder.file("a.txt"), small_text), "");
}

TEST(InputFile, AFifoIsRefusedAtOnceWithoutWaitingForAWriter) {
  wobble::testing::TemporaryFolder folder;
  const std::string path = folder.file("pipe.txt");
  ASSERT_EQ(mkfifo(path.c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(error_reading(path),
            path + ": is a FIFO (named pipe), not a regular file, expected a test file");
  // No writer ever comes, so a blocking open would never return; 10 s only guards the test.
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
}

TEST(InputFile, ADeviceIsRefusedNotStreamed) {
  EXPECT_EQ(error_reading("/dev/zero"),
            "/dev/zero: is a character device, not a regular file, expected a test file");
  wobble::testing::TemporaryFolder folder;
  std::filesystem::create_symlink("/dev/zero", folder.file("zero.txt"));
  EXPECT_NE(error_reading(folder.file("zero.txt")).find("character device"), std::string::npos);
}

TEST(InputFile, AFolderIsCalledAFolder) {
  wobble::testing::TemporaryFolder folder;
  EXPECT_EQ(error_reading(folder.path().string()),
            folder.path().string() + ": is a folder, expected a test file");
}

TEST(InputFile, AFileOverTheLimitIsRefusedFromItsSizeNamingTheLimit) {
  wobble::testing::TemporaryFolder folder;
  const std::string path = folder.file("big.txt");
  std::ofstream(path).close();
  std::filesystem::resize_file(path, 5'000'000'000u);  // sparse: nothing is written or read
  constexpr FileKind limited{"a test file", 2 * 1024 * 1024};
  EXPECT_EQ(error_reading(path, limited),
            path +
                ": is 5,000,000,000 bytes, above Wobble's limit of 2,097,152 bytes (2 MiB) "
                "for a test file");
  std::filesystem::resize_file(path, 101);
  EXPECT_NE(error_reading(path).find("above Wobble's limit of 100 bytes"), std::string::npos);
  std::filesystem::resize_file(path, 100);
  EXPECT_EQ(error_reading(path), "");
}

TEST(InputFile, PathsThatCannotBeResolvedSayWhy) {
  wobble::testing::TemporaryFolder folder;
  EXPECT_EQ(error_reading(folder.file("none.txt")),
            folder.file("none.txt") + ": no such file, expected a test file");
  EXPECT_TRUE(wobble::input_file_is_missing(folder.file("none.txt")));

  std::filesystem::create_symlink("loop.txt", folder.file("loop.txt"));
  EXPECT_NE(error_reading(folder.file("loop.txt")).find("symbolic link loop"), std::string::npos);
  EXPECT_FALSE(wobble::input_file_is_missing(folder.file("loop.txt")));

  const std::string long_name = folder.file(std::string(300, 'n') + ".txt");
  EXPECT_NE(error_reading(long_name).find("longer than the filesystem allows"), std::string::npos);

  std::ofstream(folder.file("plain.txt")) << "x";
  EXPECT_NE(error_reading(folder.file("plain.txt/inside.txt")).find("not a folder"),
            std::string::npos);
}

TEST(InputFile, AFolderWithoutSearchPermissionIsNamed) {
  if (geteuid() == 0) GTEST_SKIP() << "runs as root, which passes every permission check";
  wobble::testing::TemporaryFolder folder;
  std::filesystem::create_directory(folder.file("locked"));
  std::ofstream(folder.file("locked/a.txt")) << "x";
  std::filesystem::permissions(folder.file("locked"), std::filesystem::perms::none);
  const std::string message = error_reading(folder.file("locked/a.txt"));
  std::filesystem::permissions(folder.file("locked"), std::filesystem::perms::owner_all);
  EXPECT_NE(message.find("permission denied"), std::string::npos) << message;
}

TEST(InputFile, ByteOrderMarkIsDroppedOnlyAtTheStart) {
  EXPECT_EQ(wobble::without_byte_order_mark("\xEF\xBB\xBFv 1 2 3"), "v 1 2 3");
  EXPECT_EQ(wobble::without_byte_order_mark("v\xEF\xBB\xBF"), "v\xEF\xBB\xBF");
  EXPECT_EQ(wobble::without_byte_order_mark("\xEF\xBB"), "\xEF\xBB");
  EXPECT_EQ(wobble::without_byte_order_mark(""), "");
}

TEST(InputFile, DescribeBytesGivesMebibytesWhenWhole) {
  EXPECT_EQ(wobble::describe_bytes(33'554'432), "33,554,432 bytes (32 MiB)");
  EXPECT_EQ(wobble::describe_bytes(1000), "1,000 bytes");
}

}  // namespace
