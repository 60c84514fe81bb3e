// Every file Wobble writes goes through one writer (io/atomic_file.h): links are written
// through, /dev/stdout is written in place, two outputs never share a file, and a recording
// never mixes runs. These run the program as a user would.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "run_wobble.h"

using wobble::testing::read_text;
using wobble::testing::Result;
using wobble::testing::run_wobble;
using wobble::testing::sorted_names;
using wobble::testing::TemporaryFolder;

namespace {

std::string quoted(const std::string& path) {
  return "'" + path + "'";
}

int lines(const std::string& text) {
  int count = 0;
  for (const char c : text)
    count += c == '\n';
  return count;
}

}  // namespace

TEST(OutputFiles, EveryOutputWritesThroughALinkAndKeepsIt) {
  TemporaryFolder folder;
  const std::vector<std::pair<std::string, std::string>> outputs = {
      {"--energy-csv", "energy.csv"},
      {"--convergence-csv", "convergence.csv"},
      {"--export-obj", "final.obj"}};
  std::string arguments = "cloth --headless --frames 3";
  for (const auto& [option, name] : outputs) {
    std::filesystem::create_directory(folder.file("real"));
    std::filesystem::create_symlink("real/" + name, folder.file(name));
    arguments += " " + option + " " + quoted(folder.file(name));
  }
  const Result result = run_wobble(arguments);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const auto& [option, name] : outputs) {
    EXPECT_TRUE(std::filesystem::is_symlink(folder.file(name))) << option;
    EXPECT_GT(read_text(folder.file("real/" + name)).size(), 20u) << option;
  }
}

TEST(OutputFiles, DevStdoutIsWrittenInPlaceAfterWhatWasPrinted) {
  const Result result = run_wobble("cloth --headless --frames 3 --stats --energy-csv /dev/stdout");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  // The CSV (a header and four rows), then the statistics' line, in one file.
  EXPECT_EQ(result.out.rfind("frame,time,kinetic", 0), 0u) << result.out;
  EXPECT_EQ(lines(result.out), 6) << result.out;
  EXPECT_NE(result.out.find("\"scene\":\"cloth\""), std::string::npos);
  EXPECT_TRUE(std::filesystem::is_symlink("/dev/stdout"));
}

TEST(OutputFiles, TwoOutputsOfOneFileAreRefusedBeforeAnythingIsWritten) {
  TemporaryFolder folder;
  std::filesystem::create_symlink("same.csv", folder.file("alias.csv"));
  const std::vector<std::string> spellings = {
      "--energy-csv " + quoted(folder.file("same.csv")) + " --convergence-csv " +
          quoted(folder.file("same.csv")),
      "--energy-csv " + quoted(folder.file("same.csv")) + " --convergence-csv " +
          quoted(folder.path().string() + "/./same.csv"),
      "--energy-csv " + quoted(folder.file("alias.csv")) + " --export-obj " +
          quoted(folder.file("same.csv"))};
  for (const std::string& spelling : spellings) {
    const Result result = run_wobble("cloth --headless --frames 3 " + spelling);
    EXPECT_EQ(result.exit_code, 2) << spelling;
    EXPECT_EQ(lines(result.err), 1) << result.err;
    EXPECT_NE(result.err.find("both would write"), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(folder.file("same.csv"))) << spelling;
  }
  // /dev/null takes any number of outputs.
  const Result discarded =
      run_wobble("cloth --headless --frames 2 --energy-csv /dev/null --export-obj /dev/null");
  EXPECT_EQ(discarded.exit_code, 0) << discarded.err;
}

TEST(OutputFiles, ARecordingIntoAnEarlierOneLeavesOnlyItsOwnFrames) {
  TemporaryFolder folder;
  const std::string frames = folder.file("frames");
  Result result = run_wobble("cloth --headless --frames 4 --width 64 --height 48 --record " +
                             quoted(frames) + " --export-obj-sequence " + quoted(frames));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(sorted_names(frames).size(), 8u);
  std::filesystem::copy_file(folder.file("frames/frame_00001.png"), frames + "/notes.png");
  result = run_wobble("cloth --headless --frames 2 --width 64 --height 48 --record " +
                      quoted(frames) + " --export-obj-sequence " + quoted(frames));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(sorted_names(frames),
            (std::vector<std::string>{"frame_00001.obj", "frame_00001.png", "frame_00002.obj",
                                      "frame_00002.png", "notes.png"}));
  EXPECT_NE(result.err.find("removed 4 frames of an earlier recording"), std::string::npos)
      << result.err;
}
