// The classroom plots of a split view: both sides' convergence and energy, each side's last step
// named by the solver that took it, recorded (on the right side too) only while the plots are
// open. In-process, without GL.
#include "app/viewer/instruments.h"

#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <memory>
#include <string>

#include "../../shared_constants.h"
#include "../viewer_screen.h"
#include "app/viewer/viewer.h"

namespace {

using wobble::testing::window;

std::unique_ptr<wobble::Viewer> split_viewer(const std::string& compare, bool plots) {
  wobble::ViewerSettings settings;
  settings.compare = wobble::parse_compare_settings(compare);
  settings.plots = plots;
  auto viewer = std::make_unique<wobble::Viewer>(wobble::make_builtin_scene("cloth"), settings,
                                                 wobble::builtin_scene_names());
  viewer->render(1280, 720, window, 1.0f);
  return viewer;
}

using wobble::testing::press;

// wobble cloth --compare solver=local-global,solver=lbfgs --plots: local-global on the left,
// L-BFGS on the right, and both in each plot.
TEST(Instruments, TheSplitViewPlotsBothSidesEachNamedByItsSolver) {
  const auto owner = split_viewer("solver=local-global,solver=lbfgs", true);
  wobble::Viewer& viewer = *owner;
  ASSERT_NE(viewer.session().right_side(), nullptr);
  EXPECT_EQ(viewer.session().simulation().params().solver, "local-global");
  EXPECT_EQ(viewer.session().right_side()->params().solver, "lbfgs");
  for (int frame = 0; frame < 6; ++frame)
    viewer.advance();
  const wobble::Instruments& plots = viewer.session().instruments();
  const wobble::ConvergenceTrace& left = plots.shown_trace();
  const wobble::ConvergenceTrace& right = plots.shown_right_trace();
  EXPECT_EQ(std::string(left.solver), "local-global");
  EXPECT_EQ(std::string(right.solver), "lbfgs");
  EXPECT_EQ(left.iterations(), 50);
  EXPECT_GT(right.iterations(), 0);
  EXPECT_LE(right.iterations(), 50);
  // Each side's own step: after six steps by two methods the sides are apart, and so are the
  // first iterates' energies.
  EXPECT_GT((viewer.session().simulation().positions() - viewer.session().right_side()->positions())
                .norm(),
            1e-6);
  EXPECT_NE(left.energy.front(), right.energy.front());
  const wobble::EnergyHistory& left_energy = plots.energy_history();
  const wobble::EnergyHistory& right_energy = plots.right_energy_history();
  ASSERT_EQ(left_energy.time.size(), 6u);
  ASSERT_EQ(right_energy.time.size(), 6u);
  EXPECT_EQ(right_energy.time.back(), left_energy.time.back()) << "the same dt, the same clock";
  EXPECT_NE(right_energy.total.back(), left_energy.total.back());
}

// The right side records its convergence only while the plot shows it, as the left side does,
// and the curves go with the split view.
TEST(Instruments, TheRightSideRecordsOnlyWhileThePlotsAreOpen) {
  const auto owner = split_viewer("solver=lbfgs", false);
  wobble::Viewer& viewer = *owner;
  for (int frame = 0; frame < 3; ++frame)
    viewer.advance();
  EXPECT_FALSE(viewer.session().right_side()->records_convergence());
  EXPECT_TRUE(viewer.session().instruments().shown_right_trace().energy.empty());
  EXPECT_TRUE(viewer.session().instruments().right_energy_history().time.empty());

  press(viewer, GLFW_KEY_G);  // both plots open
  for (int frame = 0; frame < 2; ++frame)
    viewer.advance();
  EXPECT_TRUE(viewer.session().right_side()->records_convergence());
  EXPECT_EQ(std::string(viewer.session().instruments().shown_right_trace().solver), "lbfgs");
  EXPECT_EQ(viewer.session().instruments().right_energy_history().time.size(), 2u);

  press(viewer, GLFW_KEY_G);  // closed
  viewer.advance();
  EXPECT_FALSE(viewer.session().right_side()->records_convergence());

  press(viewer, GLFW_KEY_G);
  press(viewer, GLFW_KEY_2);  // no split view
  viewer.advance();
  ASSERT_EQ(viewer.session().right_side(), nullptr);
  EXPECT_TRUE(viewer.session().instruments().shown_right_trace().energy.empty());
  EXPECT_TRUE(viewer.session().instruments().right_energy_history().time.empty());
  EXPECT_FALSE(viewer.session().instruments().shown_trace().energy.empty())
      << "the left side's stays";
}

}  // namespace
