// --convergence-csv and --energy-csv, run as a grader would run them: the columns, the rows,
// and numbers that agree with what Wobble exports of the same run.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../run_wobble.h"
#include "io/load_scene.h"
#include "io/read_obj.h"

namespace {

using wobble::testing::read_text;
using wobble::testing::run_wobble;
using wobble::testing::TemporaryFolder;

// The rows of a CSV file after its header, each as numbers; the header is returned in `header`.
// The columns after the first `numbers` (all by default) are text, into `text` row by row.
std::vector<std::vector<double>> read_csv(const std::string& path, std::string& header,
                                          std::size_t numbers = 1000,
                                          std::vector<std::vector<std::string>>* text = nullptr) {
  std::istringstream in(read_text(path));
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::vector<std::string> words;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) {
      if (row.size() < numbers) {
        row.push_back(std::stod(cell));
      } else {
        words.push_back(cell);
      }
    }
    rows.push_back(row);
    if (text) text->push_back(words);
  }
  return rows;
}

TEST(InstrumentCsv, KineticEnergyMatchesTheExportedPositions) {
  TemporaryFolder folder;
  const std::string energy = folder.file("energy.csv");
  const wobble::testing::Result result =
      run_wobble("cloth --headless --frames 12 --energy-csv '" + energy +
                 "' --export-obj-sequence '" + folder.file("frames") + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::string header;
  const auto rows = read_csv(energy, header);
  EXPECT_EQ(header, "frame,time,kinetic,spring,gravity,potential,total");
  ASSERT_EQ(rows.size(), 13u) << "frame 0, the initial state, and one row a frame";

  const wobble::Scene scene = wobble::load_scene("cloth");
  const double dt = scene.params.dt;
  Eigen::MatrixXd previous = scene.network.V;  // frame 0
  for (int frame = 1; frame <= 12; ++frame) {
    char name[64];
    std::snprintf(name, sizeof(name), "frames/frame_%05d.obj", frame);
    const Eigen::MatrixXd p = wobble::read_obj(folder.file(name)).V;
    ASSERT_EQ(p.rows(), scene.network.V.rows());
    double kinetic = 0.0, gravity = 0.0;
    for (Eigen::Index i = 0; i < p.rows(); ++i) {
      kinetic += 0.5 * scene.network.m(i) * ((p.row(i) - previous.row(i)) / dt).squaredNorm();
      gravity += scene.network.m(i) * 9.81 * p(i, 1);
    }
    const std::vector<double>& row = rows[frame];
    EXPECT_EQ(row[0], frame);
    EXPECT_NEAR(row[1], frame * dt, 1e-12);
    // The OBJ's numbers round-trip exactly; the sums differ only in the order of additions.
    EXPECT_NEAR(row[2], kinetic, 1e-9 * kinetic + 1e-15) << "frame " << frame;
    EXPECT_NEAR(row[4], gravity, 1e-9 * std::abs(gravity)) << "frame " << frame;
    EXPECT_NEAR(row[5], row[3] + row[4], 1e-12 * std::abs(row[5]));
    EXPECT_NEAR(row[6], row[2] + row[5], 1e-12 * std::abs(row[6]));
    previous = p;
  }
  EXPECT_GT(rows[12][2], rows[1][2]) << "the cloth falls: it speeds up";
}

TEST(InstrumentCsv, ConvergenceRowsForEveryIterationOfEveryStep) {
  TemporaryFolder folder;
  const std::string convergence = folder.file("convergence.csv");
  // Through the image path too: the headless renderer steps the same viewer.
  const wobble::testing::Result result =
      run_wobble("cloth --headless --frames 4 --iterations 7 --convergence-csv '" + convergence +
                     "' --screenshot '" + folder.file("shot.png") + "'",
                 "DISPLAY= ");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::string header;
  std::vector<std::vector<std::string>> solvers;
  const auto rows = read_csv(convergence, header, 4, &solvers);
  // The solver last, so that the first four columns read as before.
  EXPECT_EQ(header, "frame,iteration,energy,gradient_norm,solver");
  ASSERT_EQ(rows.size(), 4u * 8u) << "iterations 0 to 7 of frames 1 to 4";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), 4u);
    EXPECT_EQ(solvers[r], std::vector<std::string>{"local-global"}) << "row " << r;
    EXPECT_EQ(rows[r][0], 1 + static_cast<int>(r / 8));
    EXPECT_EQ(rows[r][1], static_cast<int>(r % 8));
    EXPECT_GT(rows[r][3], 0.0);
    if (r % 8 != 0) {
      EXPECT_LE(rows[r][2], rows[r - 1][2] + 1e-12 * std::abs(rows[r - 1][2])) << "row " << r;
    }
  }
}

// --solver lbfgs: every row says so, and the statistics name the solver too. L-BFGS's line search
// never lets the energy rise from one iterate to the next (lbfgs_solver.h).
TEST(InstrumentCsv, TheSolverColumnNamesTheSolverThatTookEachStep) {
  TemporaryFolder folder;
  const std::string convergence = folder.file("convergence.csv");
  const wobble::testing::Result result = run_wobble(
      "cloth --headless --frames 3 --iterations 6 --solver lbfgs --stats "
      "--convergence-csv '" +
      convergence + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::string header;
  std::vector<std::vector<std::string>> solvers;
  const auto rows = read_csv(convergence, header, 4, &solvers);
  EXPECT_EQ(header, "frame,iteration,energy,gradient_norm,solver");
  ASSERT_GE(rows.size(), 3u) << "at least each step's first iterate";
  ASSERT_LE(rows.size(), 3u * 7u);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    EXPECT_EQ(solvers[r], std::vector<std::string>{"lbfgs"}) << "row " << r;
    if (r > 0 && rows[r][0] == rows[r - 1][0]) {
      EXPECT_LE(rows[r][2], rows[r - 1][2]) << "row " << r;
    }
  }
  EXPECT_EQ(rows.back()[0], 3);
  // The statistics are the last line.
  std::string out = result.out;
  while (!out.empty() && out.back() == '\n')
    out.pop_back();
  const nlohmann::json stats = nlohmann::json::parse(out.substr(out.rfind('\n') + 1));
  EXPECT_EQ(stats.at("solver"), "lbfgs");
  EXPECT_EQ(stats.at("iterations"), 6);
}

TEST(InstrumentCsv, RefusedBeforeAnyWork) {
  TemporaryFolder folder;
  const wobble::testing::Result too_many = run_wobble(
      "cloth --headless --frames 100000 --convergence-csv '" + folder.file("c.csv") + "'");
  EXPECT_EQ(too_many.exit_code, 2);
  EXPECT_NE(too_many.err.find("--convergence-csv"), std::string::npos) << too_many.err;
  EXPECT_NE(too_many.err.find("fewer --frames"), std::string::npos) << too_many.err;
  const wobble::testing::Result no_folder =
      run_wobble("cloth --headless --energy-csv '" + folder.file("missing/e.csv") + "'");
  EXPECT_EQ(no_folder.exit_code, 2);
  EXPECT_NE(no_folder.err.find("--energy-csv"), std::string::npos) << no_folder.err;
  const wobble::testing::Result window = run_wobble("cloth --energy-csv e.csv");
  EXPECT_EQ(window.exit_code, 2);
  EXPECT_NE(window.err.find("needs --frames"), std::string::npos) << window.err;
  EXPECT_EQ(folder.entries(), std::vector<std::string>{}) << "nothing written";
}

}  // namespace
