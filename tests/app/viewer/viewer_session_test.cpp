// ViewerSession, the viewer's scene and simulation side, on its own (no panel, no GL): the
// picker's catalogue follows the scenes opened and saved, the figures are the state shown (a
// copy while a batch runs), a failed step is described and a reset clears it.
#include "app/viewer/viewer_session.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "sim/shapes/builtin_scenes.h"

namespace {

std::unique_ptr<wobble::Simulation> simulation_of(const wobble::Scene& scene) {
  return std::make_unique<wobble::Simulation>(scene.network, scene.pins, scene.params);
}

// A session with the cloth open, the picker offering the built-in scenes.
struct SessionFixture {
  SessionFixture() : session(wobble::builtin_scene_names(), "cloth", "") {
    const wobble::Scene cloth = wobble::make_builtin_scene("cloth");
    session.open(cloth, simulation_of(cloth));
  }
  wobble::ViewerSession session;
};

TEST(ViewerSession, ThePickerShowsTheSceneOpenAndAddsOnesFromElsewhere) {
  SessionFixture f;
  const std::vector<std::string> names = wobble::builtin_scene_names();
  ASSERT_EQ(f.session.scene_labels().size(), names.size());
  ASSERT_EQ(f.session.scene_choices().size(), names.size());
  EXPECT_EQ(f.session.scene_labels()[f.session.scene_index()], "cloth");
  EXPECT_EQ(f.session.scene_source(), "cloth");

  wobble::Scene elsewhere = wobble::make_builtin_scene("cloth");
  elsewhere.name = "my cloth";
  f.session.open(elsewhere, simulation_of(elsewhere));
  EXPECT_EQ(f.session.scene_labels().size(), names.size() + 1);
  EXPECT_EQ(f.session.scene_labels()[f.session.scene_index()], "my cloth");
  // A saved scene is offered once, under its file's name.
  f.session.offer("/tmp/saved.json");
  f.session.offer("/tmp/saved.json");
  EXPECT_EQ(f.session.scene_sources().back(), "/tmp/saved.json");
  EXPECT_EQ(f.session.scene_sources().size(), names.size() + 2);
}

TEST(ViewerSession, AFreeVertexHeldIsNotCountedAmongThePins) {
  SessionFixture f;
  const int pins = f.session.stats().pins;
  EXPECT_EQ(pins, f.session.simulation().pin_count());
  bool held = true;
  f.session.set_free_vertex_held([&held] { return held; });
  EXPECT_EQ(f.session.stats().pins, pins - 1);
  held = false;
  EXPECT_EQ(f.session.stats().pins, pins);
}

TEST(ViewerSession, WhileABatchRunsTheFiguresAreTheCopyTakenBeforeIt) {
  SessionFixture f;
  f.session.copy_shown_figures();
  f.session.start_batch(3);
  // The batch is the caller's here, finished already, but not yet taken: the UI still shows the
  // state it started from.
  EXPECT_EQ(f.session.stats().steps, 0);
  EXPECT_EQ(f.session.shown_time().seconds, 0.0);
  EXPECT_FALSE(f.session.finish_batch(false));
  EXPECT_EQ(f.session.stats().steps, 3);
  const wobble::FrameTime time = f.session.shown_time();
  EXPECT_EQ(time.dt, f.session.simulation().params().dt);
  EXPECT_EQ(time.seconds, f.session.simulation().time());
  EXPECT_GT(f.session.step_times().step_ms, 0.0f);
}

TEST(ViewerSession, AFailedStepIsDescribedAndAResetClearsIt) {
  SessionFixture f;
  // A pin target a thousand diagonals away: the step jumps and is rolled back.
  wobble::Simulation& simulation = f.session.host().simulation();
  simulation.set_pin_target(simulation.pinned_vertices().front(), Eigen::Vector3d(1e6, 0, 0));
  f.session.start_batch(1);
  EXPECT_TRUE(f.session.finish_batch(/*dragging=*/true));
  const std::string& warning = f.session.step_warning();
  EXPECT_NE(warning.find("Paused at step 1"), std::string::npos) << warning;
  EXPECT_NE(warning.find("held vertex"), std::string::npos) << warning;
  EXPECT_EQ(f.session.stats().warning, warning);
  f.session.after_reset();
  EXPECT_EQ(f.session.step_warning(), "");
}

TEST(ViewerSession, OneStepAskedIsTakenOnceEvenPaused) {
  SessionFixture f;
  f.session.ask_one_step();
  EXPECT_TRUE(f.session.one_step_asked());
  EXPECT_EQ(f.session.steps_to_start(/*paused=*/true, false, std::nullopt, 0.0), 1);
  EXPECT_FALSE(f.session.one_step_asked());
  EXPECT_EQ(f.session.steps_to_start(/*paused=*/true, false, std::nullopt, 0.0), 0);
}

TEST(ViewerSession, TheConvergenceIsRecordedWhileTheCsvNeedsItThroughNewScenes) {
  SessionFixture f;
  EXPECT_FALSE(f.session.simulation().records_convergence());
  f.session.set_convergence_required(true);
  EXPECT_TRUE(f.session.simulation().records_convergence());
  const wobble::Scene jelly = wobble::make_builtin_scene("jelly");
  f.session.open(jelly, simulation_of(jelly));
  EXPECT_TRUE(f.session.simulation().records_convergence());
}

}  // namespace
