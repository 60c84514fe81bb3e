// The wobble executable as users and scripts run it: exit codes, messages, files, statistics.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <Eigen/Core>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../run_wobble.h"

namespace {

using wobble::testing::TemporaryFolder;

using wobble::testing::Result;
using wobble::testing::run_wobble;

std::string read(const std::string& path) {
  return wobble::testing::read_text(path);
}

std::string last_line(const std::string& text) {
  std::string trimmed = text;
  while (!trimmed.empty() && trimmed.back() == '\n')
    trimmed.pop_back();
  const std::size_t newline = trimmed.rfind('\n');
  return newline == std::string::npos ? trimmed : trimmed.substr(newline + 1);
}

int count_lines(const std::string& text) {
  int lines = 0;
  for (char c : text)
    lines += c == '\n';
  return lines;
}

TEST(CommandLine, HelpListsTheOptionsAndSucceeds) {
  const Result result = run_wobble("--help");
  EXPECT_EQ(result.exit_code, 0);
  for (const char* option : {"--headless", "--frames", "--export-obj", "--k", "--dt",
                             "--iterations", "--solver", "--stats", "--version"}) {
    EXPECT_NE(result.out.find(option), std::string::npos) << option;
  }
  EXPECT_EQ(result.err, "");
}

TEST(CommandLine, VersionPrintsOneLine) {
  const Result result = run_wobble("--version");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_EQ(result.out.rfind("wobble ", 0), 0u) << result.out;
  EXPECT_EQ(count_lines(result.out), 1);
}

TEST(CommandLine, BadUsageExitsWithCode2AndOneLine) {
  const char* cases[][2] = {
      {"--bogus --headless", "--bogus"},
      {"--headless --frames 0", "--frames"},
      {"--headless --frames -3", "--frames"},
      {"--headless --frames many", "--frames"},
      {"--headless --frames 1.5", "got '1.5'"},
      {"--headless --frames 99999999999999999999", "got '99999999999999999999'"},
      {"--headless --k ''", "--k: expected a positive finite number, got ''"},
      {"--headless --export-obj ''", "--export-obj: expected a file path"},
      {"--headless --export-obj /", "is a folder"},
      {"--headless --k -5", "--k"},
      {"--headless --k nan", "--k"},
      {"--headless --k 1e12", "limit"},
      {"--headless --dt 0", "--dt"},
      {"--headless --iterations 20000", "5000"},
      {"curtain --headless", "curtain"},
      {"--headless --color-by stress",
       "--color-by: expected material, strain, speed, contacts or volume, got 'stress'"},
      {"--headless --color-by ''",
       "--color-by: expected material, strain, speed, contacts or volume, got ''"},
      {"--headless --compare iterations=0", "--compare: iterations: expected a whole number"},
      {"--headless --compare speed=2", "--compare: unknown setting 'speed'"},
      {"--headless --student /nonexistent", "--student: shows the student's step"},
      {"--headless --student /nonexistent --screenshot x.png",
       "--student /nonexistent: check-assignment: /nonexistent: no such folder"},
      {"--student d --compare k=5", "--student, --compare: both take the split view"},
      {"--headless --convergence-csv ''", "--convergence-csv: expected a file path"},
      {"--headless --solver bfgs", "--solver: expected local-global or lbfgs, got 'bfgs'"},
      {"--headless --solver ''", "--solver: expected local-global or lbfgs, got ''"},
      {"--headless --solver", "--solver"},
      {"--headless --compare solver=newton --screenshot x.png",
       "--compare: solver: expected local-global or lbfgs, got 'newton'"},
      {"--compare solver=local-global,solver=lbfgs --solver lbfgs",
       "--solver, --compare: both set the left side's solver"},
  };
  for (const auto& [arguments, expected] : cases) {
    SCOPED_TRACE(arguments);
    const Result result = run_wobble(arguments);
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(count_lines(result.err), 1) << result.err;
    EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
    EXPECT_EQ(result.out, "");
  }
}

TEST(CommandLine, ExportObjWritesTheSaggingCloth) {
  TemporaryFolder folder;
  const std::string path = folder.file("cloth.obj");
  const Result result = run_wobble("cloth --headless --frames 30 --export-obj '" + path + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::istringstream lines(read(path));
  std::string line;
  int vertices = 0, faces = 0;
  double lowest = 1e9, highest = -1e9;
  while (std::getline(lines, line)) {
    if (line.rfind("v ", 0) == 0) {
      ++vertices;
      double x, y, z;
      std::istringstream(line.substr(2)) >> x >> y >> z;
      lowest = std::min(lowest, y);
      highest = std::max(highest, y);
    } else if (line.rfind("f ", 0) == 0) {
      ++faces;
    }
  }
  EXPECT_EQ(vertices, 1600);
  EXPECT_EQ(faces, 2 * 39 * 39);
  // It started flat at y = 1.2 and hangs from its pins there; after half a second it is at the
  // bottom of its first swing.
  EXPECT_NEAR(highest, 1.2, 1e-6);
  EXPECT_LT(lowest, 0.6);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"cloth.obj"});
}

// Vertex `index` (0-based) of an OBJ file as Wobble writes it.
Eigen::Vector3d obj_vertex(const std::string& path, int index) {
  std::istringstream lines(read(path));
  std::string line;
  int seen = 0;
  while (std::getline(lines, line)) {
    if (line.rfind("v ", 0) != 0) continue;
    if (seen++ == index) {
      Eigen::Vector3d p;
      std::istringstream(line.substr(2)) >> p.x() >> p.y() >> p.z();
      return p;
    }
  }
  ADD_FAILURE() << "no vertex " << index << " in " << path;
  return Eigen::Vector3d::Zero();
}

TEST(CommandLine, DragHoldsAVertexOnItsScriptedPath) {
  TemporaryFolder folder;
  // Vertex 820 is in the middle of the built-in cloth, which starts flat at y = 1.2.
  const Result rest =
      run_wobble("cloth --headless --frames 1 --iterations 1 --dt 1e-9 --export-obj '" +
                 folder.file("rest.obj") + "'");
  ASSERT_EQ(rest.exit_code, 0) << rest.err;
  const Eigen::Vector3d start = obj_vertex(folder.file("rest.obj"), 820);
  const Result dragged = run_wobble(
      "cloth --headless --frames 40 --iterations 10 --drag 820:0.1,0.3,-0.2@1-40 "
      "--export-obj '" +
      folder.file("dragged.obj") + "'");
  ASSERT_EQ(dragged.exit_code, 0) << dragged.err;
  const Eigen::Vector3d end = obj_vertex(folder.file("dragged.obj"), 820);
  EXPECT_LT((end - start - Eigen::Vector3d(0.1, 0.3, -0.2)).norm(), 1e-5) << end.transpose();
}

TEST(CommandLine, AStepThatFailsExitsWith1AndWritesNoExport) {
  TemporaryFolder folder;
  const std::string objs = folder.file("objs");
  const Result result =
      run_wobble("cloth --headless --frames 5 --drag 0:1e5,0,0@3-3 --export-obj '" +
                 folder.file("out.obj") + "' --export-obj-sequence '" + objs + "'");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(count_lines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("frame 3"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("rolled back"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(folder.file("out.obj")));
  // The two good frames were written, and nothing after them.
  EXPECT_EQ(wobble::testing::sorted_names(objs),
            (std::vector<std::string>{"frame_00001.obj", "frame_00002.obj"}));
}

TEST(CommandLine, ExportToAMissingFolderFailsBeforeSimulatingAndWritesNothing) {
  TemporaryFolder folder;
  const Result result =
      run_wobble("cloth --headless --frames 100000 --export-obj '" + folder.file("no/x.obj") + "'");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("does not exist"), std::string::npos) << result.err;
  EXPECT_TRUE(folder.entries().empty());
}

TEST(CommandLine, StatsIsOneJsonObjectOnTheLastLine) {
  const Result result = run_wobble("jelly --headless --frames 5 --iterations 7 --k 900 --stats");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json stats = nlohmann::json::parse(last_line(result.out));
  EXPECT_EQ(stats.at("vertices"), 729);
  EXPECT_EQ(stats.at("pinned"), 81);
  EXPECT_EQ(stats.at("iterations"), 7);
  EXPECT_EQ(stats.at("frames"), 5);
  EXPECT_EQ(stats.at("k"), 900.0);
  EXPECT_GT(stats.at("springs").get<int>(), 729);
  for (const char* key : {"precompute_ms", "step_ms_median", "step_ms_min", "step_ms_max",
                          "local_ms_median", "global_ms_median"}) {
    ASSERT_TRUE(stats.contains(key)) << key;
    EXPECT_GT(stats.at(key).get<double>(), 0.0) << key;
  }
  EXPECT_LE(stats.at("step_ms_min").get<double>(), stats.at("step_ms_median").get<double>());
  EXPECT_LE(stats.at("step_ms_median").get<double>(), stats.at("step_ms_max").get<double>());
  EXPECT_EQ(stats.at("chebyshev"), false);
  EXPECT_EQ(stats.at("chebyshev_rho"), 0.0);
}

TEST(CommandLine, StatsGivesTheEstimatedSpectralRadiusWithChebyshev) {
  const Result result = run_wobble("jelly --headless --frames 2 --chebyshev --stats");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json stats = nlohmann::json::parse(last_line(result.out));
  EXPECT_EQ(stats.at("chebyshev"), true);
  // The jelly's plain iterations shrink their updates by about 0.94 each.
  EXPECT_GT(stats.at("chebyshev_rho").get<double>(), 0.8);
  EXPECT_LT(stats.at("chebyshev_rho").get<double>(), 0.999);
}

// --solver picks the step solver over the scene's; local-global is the default, to the bit.
TEST(CommandLine, SolverOverridesTheScenesAndLocalGlobalIsTheDefault) {
  TemporaryFolder folder;
  std::ofstream(folder.file("lbfgs.json"))
      << R"({"mesh": {"generator": "cloth", "resolution": 12}, "pins": "top-corners",
             "simulation": {"solver": "lbfgs"}})";
  const auto solver_of = [&](const std::string& arguments) {
    const Result result = run_wobble("'" + folder.file("lbfgs.json") + "' --headless --frames 2 " +
                                     arguments + " --stats");
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return nlohmann::json::parse(last_line(result.out)).at("solver").get<std::string>();
  };
  EXPECT_EQ(solver_of(""), "lbfgs");
  EXPECT_EQ(solver_of("--solver local-global"), "local-global");
  EXPECT_EQ(solver_of("--solver lbfgs"), "lbfgs");

  const auto positions = [&](const std::string& name, const std::string& arguments) {
    const Result result = run_wobble("cloth --headless --frames 20 " + arguments +
                                     " --export-obj '" + folder.file(name) + "'");
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return read(folder.file(name));
  };
  const std::string plain = positions("plain.obj", "");
  EXPECT_EQ(positions("local_global.obj", "--solver local-global"), plain);
  EXPECT_NE(positions("lbfgs.obj", "--solver lbfgs"), plain) << "another method, other positions";
}

TEST(CommandLine, HeadlessRunsAreDeterministic) {
  TemporaryFolder folder;
  const std::string a = folder.file("a.obj"), b = folder.file("b.obj");
  ASSERT_EQ(run_wobble("jelly --headless --frames 20 --export-obj '" + a + "'").exit_code, 0);
  ASSERT_EQ(run_wobble("jelly --headless --frames 20 --export-obj '" + b + "'").exit_code, 0);
  EXPECT_EQ(read(a), read(b));
  EXPECT_NE(read(a).find("\nf "), std::string::npos);
}

}  // namespace
