// wobble --student: the viewer's split view with a student's step on the right, driven
// in-process with step servers that scripts/check-assignment.sh built (the
// CheckAssignment.BuildStepServers fixture): the seed's own step stays on Wobble's, a crashing
// one stops the right side with the reason and the left goes on.
#include <gtest/gtest.h>
#include <unistd.h>

#include "app/viewer/viewer.h"
#include "io/load_scene.h"

namespace {

std::string server(const std::string& name) {
  const std::string path = std::string(WOBBLE_STEP_SERVERS) + "/" + name;
  if (access(path.c_str(), X_OK) != 0) ADD_FAILURE() << path << " is missing";
  return path;
}

std::unique_ptr<wobble::Viewer> student_viewer(wobble::Scene scene,
                                               const std::string& server_name) {
  wobble::ViewerSettings settings;
  settings.student_server = server(server_name);
  auto viewer =
      std::make_unique<wobble::Viewer>(std::move(scene), settings, std::vector<std::string>());
  viewer->render(1280, 720, Eigen::Vector2f(1280.0f, 720.0f), 1.0f);
  return viewer;
}

TEST(StudentView, TheSeedsOwnStepStaysOnWobbles) {
  for (const std::string& scene :
       {std::string(WOBBLE_ASSETS_DIR) + "/course/banner.json", std::string("cloth")}) {
    SCOPED_TRACE(scene);
    const auto viewer = student_viewer(wobble::load_scene(scene), "reference");
    ASSERT_NE(viewer->session().right_side(), nullptr);
    EXPECT_EQ(viewer->session().simulation().params().first_iterate,
              wobble::FirstIterate::current_positions)
        << "Wobble's side takes the seed's step";
    for (int frame = 0; frame < 20; ++frame)
      viewer->advance();
    EXPECT_EQ(viewer->session().right_side_warning(), "");
    // The same function on both sides; only the order of sums may differ.
    EXPECT_LT(viewer->session().student_distance(), 1e-9);
    // And the shape did move: the distance is measured on a falling cloth, not a resting one.
    EXPECT_GT(
        (viewer->session().right_side()->positions() - viewer->session().scene().network.V).norm(),
        0.01);
  }
}

TEST(StudentView, ACrashStopsTheRightSideWithTheReasonAndTheLeftGoesOn) {
  // That server crashes once vertex 0 is 5 cm below y = 0: here the free end of a pendulum.
  wobble::Scene pendulum;
  pendulum.name = "pendulum";
  pendulum.network.V = Eigen::MatrixXd(2, 3);
  pendulum.network.V << 0.3, 0.0, 0.0, 0.0, 0.0, 0.0;
  pendulum.network.E = Eigen::MatrixXi(1, 2);
  pendulum.network.E << 0, 1;
  pendulum.network.m = Eigen::Vector2d(1.0, 1.0);
  pendulum.pins = {1};
  const auto viewer = student_viewer(std::move(pendulum), "crashing");
  for (int frame = 0; frame < 30; ++frame)
    viewer->advance();
  EXPECT_NE(viewer->session().right_side_warning().find("SIG"), std::string::npos)
      << viewer->session().right_side_warning();
  EXPECT_EQ(viewer->session().simulation().steps_taken(), 30);
}

}  // namespace
