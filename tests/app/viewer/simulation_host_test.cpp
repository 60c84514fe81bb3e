// SimulationHost, the viewer's simulation side, on its own: batches on the caller or on the
// stepping thread give the same positions, edits made while a batch runs wait for it and keep
// their order, the step limit and pausing hold, and the observers see each good step.
#include "app/viewer/simulation_host.h"

#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "sim/shapes/builtin_scenes.h"

namespace {

std::unique_ptr<wobble::Simulation> cloth_simulation() {
  const wobble::Scene scene = wobble::make_builtin_scene("cloth");
  return std::make_unique<wobble::Simulation>(scene.network, scene.pins, scene.params);
}

TEST(SimulationHost, ABatchOnTheThreadGivesTheCallersPositions) {
  wobble::SimulationHost on_caller, on_thread;
  on_caller.replace(cloth_simulation());
  on_thread.replace(cloth_simulation());
  on_thread.step_on_thread([] {});
  for (wobble::SimulationHost* host : {&on_caller, &on_thread}) {
    host->start_batch(5, false, false);
    const wobble::Batch* batch = host->finish_batch();
    ASSERT_NE(batch, nullptr);
    EXPECT_EQ(batch->steps_taken, 5);
    EXPECT_EQ(batch->timings.size(), 5u);
  }
  EXPECT_EQ(on_caller.simulation().positions(), on_thread.simulation().positions());
  EXPECT_EQ(on_thread.simulation().steps_taken(), 5);
}

TEST(SimulationHost, EditsDuringABatchWaitForItAndKeepTheirOrder) {
  wobble::SimulationHost host;
  host.replace(cloth_simulation());
  // Between batches an edit is made at once.
  std::vector<std::string> done;
  EXPECT_TRUE(host.change([&] { done.push_back("now"); }));
  EXPECT_EQ(done, std::vector<std::string>{"now"});

  std::atomic<bool> release{false};
  host.step_on_thread([] {});
  host.set_after_step([&](const wobble::Simulation&) {
    while (!release.load()) {
    }
  });
  host.start_batch(1, false, false);
  EXPECT_FALSE(host.change([&] { done.push_back("first"); }));
  EXPECT_FALSE(host.change([&] {
    done.push_back("second");
    host.simulation().apply(wobble::with_setting(host.simulation().params(), "k", 2000.0));
  }));
  EXPECT_TRUE(host.changes_waiting());
  EXPECT_EQ(done.size(), 1u) << "nothing done while the batch runs";
  release = true;
  host.finish_batch();
  host.hand_over_changes();
  EXPECT_EQ(done, (std::vector<std::string>{"now", "first", "second"}));
  EXPECT_FALSE(host.changes_waiting());
  EXPECT_EQ(host.simulation().params().k, 2000.0);
}

TEST(SimulationHost, StepsToStartHonourPauseOneStepAndTheLimit) {
  wobble::SimulationHost host;
  host.replace(cloth_simulation());
  const double frame = 1.0 / 60.0;
  EXPECT_EQ(host.steps_to_start(false, /*paused=*/true, true, std::nullopt, frame, 0.001), 0);
  EXPECT_EQ(host.steps_to_start(/*step_once=*/true, true, true, std::nullopt, frame, 0.001), 1);
  EXPECT_EQ(host.steps_to_start(false, false, true, std::nullopt, frame, 0.001), 1)
      << "headless: one a frame";
  host.set_step_limit(2);
  host.start_batch(2, false, false);
  host.finish_batch();
  EXPECT_EQ(host.steps_to_start(false, false, true, std::nullopt, frame, 0.001), 0)
      << "at the limit";
  EXPECT_EQ(host.steps_to_start(true, false, true, std::nullopt, frame, 0.001), 0)
      << "not even one asked for";
  // Play past it (the page, paused there): on; a scene opened next stops at the limit again.
  host.pass_step_limit();
  EXPECT_FALSE(host.at_step_limit());
  EXPECT_EQ(host.steps_to_start(false, false, true, std::nullopt, frame, 0.001), 1);
  host.replace(cloth_simulation());
  host.start_batch(2, false, false);
  host.finish_batch();
  EXPECT_TRUE(host.at_step_limit()) << "the next scene stops at the limit too";
  EXPECT_EQ(host.steps_to_start(false, false, true, std::nullopt, frame, 0.001), 0);
}

TEST(SimulationHost, ObserversSeeEachGoodStepAfterTheSplitView) {
  wobble::SimulationHost host;
  host.replace(cloth_simulation());
  std::vector<std::string> seen;
  host.set_after_step([&](const wobble::Simulation& s) {
    seen.push_back("after " + std::to_string(s.steps_taken()));
  });
  host.set_step_observer([&](const wobble::Simulation& s) {
    seen.push_back("observer " + std::to_string(s.steps_taken()));
  });
  host.start_batch(2, false, false);
  host.finish_batch();
  EXPECT_EQ(seen, (std::vector<std::string>{"after 1", "observer 1", "after 2", "observer 2"}));
}

TEST(SimulationHost, AFailedStepEndsTheBatchAndSaysWhich) {
  wobble::SimulationHost host;
  host.replace(cloth_simulation());
  // A pin target a thousand diagonals away: the step jumps and is rolled back.
  const int pin = host.simulation().pinned_vertices().front();
  host.simulation().set_pin_target(pin, Eigen::Vector3d(1e6, 0.0, 0.0));
  int observed = 0;
  host.set_step_observer([&](const wobble::Simulation&) { ++observed; });
  host.start_batch(3, false, false);
  const wobble::Batch* batch = host.finish_batch();
  ASSERT_NE(batch, nullptr);
  EXPECT_NE(batch->status, wobble::StepStatus::ok);
  EXPECT_EQ(batch->failed_step, 1);
  EXPECT_EQ(batch->steps_taken, 0);
  EXPECT_EQ(observed, 0) << "a rolled-back step is no step";
}

}  // namespace
