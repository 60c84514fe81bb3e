#include "io/atomic_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

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
  wobble::write_file_atomically(path, "first\n");
  EXPECT_EQ(read(path), "first\n");
  wobble::write_file_atomically(path, std::string(100000, 'x'));
  EXPECT_EQ(read(path), std::string(100000, 'x'));
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, FailureThrowsAndLeavesNothingBehind) {
  TemporaryFolder folder;
  EXPECT_THROW(wobble::write_file_atomically(folder.file("missing/out.txt"), "x"),
               wobble::OutputError);
  // Renaming a file over a folder fails after the temporary file was written: it must go.
  std::filesystem::create_directory(folder.file("taken"));
  EXPECT_THROW(wobble::write_file_atomically(folder.file("taken"), "x"), wobble::OutputError);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"taken"});
}

TEST(AtomicFile, CheckOutputPathRefusesMissingFoldersAndFolders) {
  TemporaryFolder folder;
  EXPECT_NO_THROW(wobble::check_output_path(folder.file("fine.obj")));
  try {
    wobble::check_output_path(folder.file("nope/out.obj"));
    FAIL() << "accepted a path in a missing folder";
  } catch (const wobble::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("does not exist"), std::string::npos);
  }
  EXPECT_THROW(wobble::check_output_path(folder.path().string()), wobble::InputError);
  EXPECT_THROW(wobble::check_output_path(""), wobble::InputError);
}

}  // namespace
