#include "io/output_target.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "io/atomic_file.h"
#include "sim/input_error.h"
#include "temporary_folder.h"

using wobble::OutputTarget;
using wobble::testing::TemporaryFolder;

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

OutputTarget resolved(const std::string& path) {
  OutputTarget target;
  const std::string problem = wobble::resolve_output(path, target);
  EXPECT_EQ(problem, "") << path;
  return target;
}

}  // namespace

TEST(OutputTarget, ALinkIsWrittenThroughAndStaysALink) {
  TemporaryFolder folder;
  std::filesystem::create_symlink("real.csv", folder.file("link.csv"));
  wobble::write_output_file(folder.file("link.csv"), "first\n");
  EXPECT_TRUE(std::filesystem::is_symlink(folder.file("link.csv")));
  EXPECT_EQ(read_text(folder.file("real.csv")), "first\n");
  // Once the target exists, it is replaced atomically, and the link still points at it.
  wobble::write_output_file(folder.file("link.csv"), "second\n");
  EXPECT_TRUE(std::filesystem::is_symlink(folder.file("link.csv")));
  EXPECT_EQ(read_text(folder.file("real.csv")), "second\n");
  // A chain of links, one of them absolute, ends at the same file.
  std::filesystem::create_symlink(folder.file("link.csv"), folder.file("chain.csv"));
  wobble::write_output_file(folder.file("chain.csv"), "third\n");
  EXPECT_EQ(read_text(folder.file("real.csv")), "third\n");
  EXPECT_EQ(resolved(folder.file("chain.csv")).identity,
            resolved(folder.file("real.csv")).identity);
  EXPECT_EQ(resolved(folder.file("chain.csv")).kind, OutputTarget::Kind::regular_file);
}

TEST(OutputTarget, ADanglingLinkMakesItsTargetOrIsRefusedWithItsFolder) {
  TemporaryFolder folder;
  std::filesystem::create_symlink("made.obj", folder.file("dangling.obj"));
  const OutputTarget target = resolved(folder.file("dangling.obj"));
  EXPECT_EQ(target.kind, OutputTarget::Kind::new_file);
  EXPECT_EQ(target.path, folder.file("made.obj"));
  wobble::write_output_file(folder.file("dangling.obj"), "v 0 0 0\n");
  EXPECT_EQ(read_text(folder.file("made.obj")), "v 0 0 0\n");
  EXPECT_TRUE(std::filesystem::is_symlink(folder.file("dangling.obj")));

  std::filesystem::create_symlink("nowhere/x.obj", folder.file("lost.obj"));
  OutputTarget lost;
  const std::string problem = wobble::resolve_output(folder.file("lost.obj"), lost);
  EXPECT_NE(problem.find("is a link to '" + folder.file("nowhere/x.obj") + "', whose folder"),
            std::string::npos)
      << problem;
  EXPECT_THROW(wobble::check_output_path("--energy-csv", folder.file("lost.obj")),
               wobble::InputError);
  EXPECT_FALSE(std::filesystem::exists(folder.file("nowhere")));
}

TEST(OutputTarget, NewFilesSpeltTwoWaysAreOneFile) {
  TemporaryFolder folder;
  std::filesystem::create_directory(folder.file("sub"));
  EXPECT_EQ(resolved(folder.file("sub/../x.csv")).identity,
            resolved(folder.file("x.csv")).identity);
  EXPECT_NE(resolved(folder.file("y.csv")).identity, resolved(folder.file("x.csv")).identity);
}

TEST(OutputTarget, AFifoIsWrittenInPlaceForItsReader) {
  TemporaryFolder folder;
  const std::string fifo = folder.file("pipe.csv");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(resolved(fifo).kind, OutputTarget::Kind::in_place);
  std::string received;
  std::thread reader([&] { received = read_text(fifo); });
  wobble::write_output_file(fifo, std::string(100000, 'x'));
  reader.join();
  EXPECT_EQ(received, std::string(100000, 'x'));
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  // Nobody reading: it gives up after the wait instead of hanging.
  const std::string failure = wobble::write_in_place(resolved(fifo), "x", 0.1);
  EXPECT_NE(failure.find("is a FIFO that nobody read"), std::string::npos) << failure;
}

TEST(OutputTarget, DescriptorNamesWriteToTheOpenDescriptor) {
  int ends[2];
  ASSERT_EQ(pipe(ends), 0);
  for (const std::string& name :
       {"/dev/fd/" + std::to_string(ends[1]), "/proc/self/fd/" + std::to_string(ends[1]),
        "/proc/" + std::to_string(getpid()) + "/fd/" + std::to_string(ends[1])}) {
    const OutputTarget target = resolved(name);
    EXPECT_EQ(target.kind, OutputTarget::Kind::descriptor) << name;
    EXPECT_EQ(target.descriptor, ends[1]) << name;
    EXPECT_EQ(target.identity, "") << "a pipe takes one output after another";
  }
  wobble::write_output_file("/dev/fd/" + std::to_string(ends[1]), "through the pipe");
  close(ends[1]);
  char buffer[64] = {};
  EXPECT_EQ(read(ends[0], buffer, sizeof buffer - 1), 16);
  EXPECT_EQ(std::string(buffer), "through the pipe");
  // A descriptor opened only for reading cannot take an output.
  OutputTarget target;
  const std::string problem = wobble::resolve_output("/dev/fd/" + std::to_string(ends[0]), target);
  EXPECT_NE(problem.find("not open for writing"), std::string::npos) << problem;
  close(ends[0]);
  EXPECT_EQ(resolved("/dev/stdout").descriptor, 1);
  EXPECT_EQ(resolved("/dev/stderr").descriptor, 2);
}
