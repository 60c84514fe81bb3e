#include "io/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "sim/input_error.h"
#include "temporary_folder.h"

namespace {

using wobble::testing::TemporaryFolder;

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(AtomicFile, WritesAndReplacesLeavingNoTemporaryFiles) {
  TemporaryFolder folder;
  const std::string path = folder.file("out.txt");
  wobble::write_output_file(path, "first\n");
  EXPECT_EQ(read(path), "first\n");
  wobble::write_output_file(path, std::string(100000, 'x'));
  EXPECT_EQ(read(path), std::string(100000, 'x'));
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.txt"});
}

mode_t permissions(const std::string& path) {
  struct stat info {};
  EXPECT_EQ(stat(path.c_str(), &info), 0) << path;
  return info.st_mode & 07777;
}

TEST(AtomicFile, AReplacedFileKeepsItsPermissionsAndANewOneFollowsTheUmask) {
  TemporaryFolder folder;
  const mode_t previous_mask = umask(022);
  const std::string path = folder.file("image.png");
  wobble::write_output_file(path, "new");
  EXPECT_EQ(permissions(path), 0644u) << "0666 less the umask";
  for (const mode_t mode : {0600u, 0640u, 0604u, 0755u}) {
    ASSERT_EQ(chmod(path.c_str(), mode), 0);
    wobble::write_output_file(path, "replaced");
    EXPECT_EQ(permissions(path), mode);
    EXPECT_EQ(read(path), "replaced");
  }
  ASSERT_EQ(chmod(path.c_str(), 04755), 0);  // set-user-ID is not carried over
  wobble::write_output_file(path, "again");
  EXPECT_EQ(permissions(path), 0755u);
  umask(previous_mask);
}

TEST(AtomicFile, FailureThrowsAndLeavesNothingBehind) {
  TemporaryFolder folder;
  EXPECT_THROW(wobble::write_output_file(folder.file("missing/out.txt"), "x"), wobble::OutputError);
  // Renaming a file over a folder fails after the temporary file was written: it must go.
  std::filesystem::create_directory(folder.file("taken"));
  EXPECT_THROW(wobble::write_output_file(folder.file("taken"), "x"), wobble::OutputError);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"taken"});
}

TEST(AtomicFile, CheckOutputPathRefusesMissingFoldersAndFolders) {
  TemporaryFolder folder;
  EXPECT_NO_THROW(wobble::check_output_path("--export-obj", folder.file("fine.obj")));
  try {
    wobble::check_output_path("--export-obj", folder.file("nope/out.obj"));
    FAIL() << "accepted a path in a missing folder";
  } catch (const wobble::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("does not exist"), std::string::npos);
  }
  EXPECT_THROW(wobble::check_output_path("--export-obj", folder.path().string()),
               wobble::InputError);
  EXPECT_THROW(wobble::check_output_path("--export-obj", ""), wobble::InputError);
  // The probe leaves nothing behind.
  EXPECT_TRUE(folder.entries().empty());
}

// The message names the option and what is wrong with the path.
std::string refusal(const std::string& path) {
  try {
    wobble::check_output_path("--export-obj", path);
  } catch (const wobble::InputError& error) {
    return error.what();
  }
  return "(accepted)";
}

TEST(AtomicFile, CheckOutputPathTakesDevicesAndFifosButRefusesLongNamesAndLoops) {
  TemporaryFolder folder;
  // Written in place, never replaced.
  EXPECT_NO_THROW(wobble::check_output_path("--export-obj", "/dev/null"));
  ASSERT_EQ(mkfifo(folder.file("pipe.obj").c_str(), 0600), 0);
  EXPECT_NO_THROW(wobble::check_output_path("--export-obj", folder.file("pipe.obj")));
  // The name fits the filesystem's 255 bytes, but its temporary file's name does not: the
  // write at the end would fail, so it fails now.
  const std::string long_name = folder.file(std::string(250, 'a') + ".obj");
  EXPECT_NE(refusal(long_name).find("File name too long"), std::string::npos) << refusal(long_name);
  std::filesystem::create_symlink("loop", folder.file("loop"));
  EXPECT_NE(refusal(folder.file("loop"))
                .find("--export-obj: '" + folder.file("loop") +
                      "' is a link in a chain of more than 40 links"),
            std::string::npos)
      << refusal(folder.file("loop"));
  std::filesystem::create_directory(folder.file("d"));
  std::filesystem::create_symlink("d", folder.file("to-folder"));
  EXPECT_NE(refusal(folder.file("to-folder")).find("is a folder"), std::string::npos)
      << refusal(folder.file("to-folder"));
  std::vector<std::string> entries = folder.entries();
  std::sort(entries.begin(), entries.end());
  EXPECT_EQ(entries, (std::vector<std::string>{"d", "loop", "pipe.obj", "to-folder"}));
}

TEST(AtomicFile, CheckOutputFolderCreatesNothing) {
  TemporaryFolder folder;
  const std::string frames = folder.file("frames");
  EXPECT_NO_THROW(wobble::check_output_folder("--record", frames, frames + "/frame_00001.png"));
  EXPECT_TRUE(folder.entries().empty());
  EXPECT_THROW(wobble::check_output_folder("--record", folder.file("a/b"), folder.file("a/b/f")),
               wobble::InputError);
  const std::string too_long = folder.file(std::string(300, 'd'));
  EXPECT_THROW(wobble::check_output_folder("--record", too_long, too_long + "/f"),
               wobble::InputError);
  wobble::make_output_folder(frames);
  EXPECT_TRUE(std::filesystem::is_directory(frames));
  EXPECT_NO_THROW(wobble::make_output_folder(frames));  // already there: fine
}

// SIGTERM in the middle of a write: the handler removes the temporary file, then the signal
// ends the process as it would have. A helper thread sends the signal while 64 MB are being
// written; whenever it lands, nothing may be left but (if the rename was reached) the file.
TEST(AtomicFileDeathTest, TerminationRemovesTheTemporaryFile) {
  GTEST_FLAG_SET(death_test_style, "fast");  // the child must see this very folder
  for (const int signal_number : {SIGTERM, SIGINT}) {
    TemporaryFolder folder;
    const std::string path = folder.file("big.obj");
    EXPECT_EXIT(
        {
          wobble::remove_temporary_file_on_termination();
          const std::string contents(64 << 20, 'x');
          std::thread sender([signal_number] {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            kill(getpid(), signal_number);
          });
          for (;;)
            wobble::write_output_file(path, contents);
        },
        ::testing::KilledBySignal(signal_number), "");
    for (const std::string& name : folder.entries())
      EXPECT_EQ(name, "big.obj") << "left behind";
  }
}

}  // namespace
