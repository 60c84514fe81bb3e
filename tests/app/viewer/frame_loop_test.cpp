// draw_frame over a host played by the test (no GL, no ImGui): a host is only the platform, and
// what differs by mode is the policy the run hands in: one step a frame or batches, stopping on a
// failed step in the loop, drawing and reading back only the frames an output wants.
#include "app/viewer/frame_loop.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "app/viewer/viewer.h"

namespace {

struct PlayedHost : wobble::FrameHost {
  wobble::PolledInput poll(const wobble::Viewer&, const wobble::FrameMeters&) override {
    ++frame;
    wobble::PolledInput input;
    input.dropped_paths = dropped;
    dropped.clear();
    return input;
  }
  double now() const override { return frame / 60.0; }
  wobble::FrameSizes sizes() override {
    wobble::FrameSizes sizes;
    sizes.width = 320;
    sizes.height = 240;
    sizes.window = Eigen::Vector2f(320.0f, 240.0f);
    return sizes;
  }
  void begin_frame() override { ++begun; }
  void bind_target() override { bound.push_back(frame); }
  void read_picture(wobble::RgbaImage& image) override {
    image.width = 320;
    image.height = 240;
    image.pixels.assign(320 * 240 * 4, static_cast<unsigned char>(frame));
    read.push_back(frame);
  }
  void present(const std::string& shown) override { title = shown; }

  long frame = 0;
  int begun = 0;
  std::vector<long> bound, read;
  std::vector<std::string> dropped;
  std::string title;
};

// Wants every third frame, as --record with a stride would.
struct EveryThird : wobble::PictureOutput {
  bool wants(const wobble::Viewer& viewer) override {
    return viewer.session().simulation().steps_taken() % 3 == 0;
  }
  void take(const wobble::Viewer& viewer,
            const std::function<void(wobble::RgbaImage&)>& read) override {
    wobble::RgbaImage image;
    read(image);
    taken.push_back(viewer.session().simulation().steps_taken());
  }
  std::vector<long> taken;
};

wobble::FramePolicy headless_policy(wobble::PictureOutput* output) {
  wobble::FramePolicy policy;
  policy.ui = wobble::FramePolicy::Ui::none;
  policy.wall_clock_figures = false;
  policy.one_step_a_frame = true;
  policy.stop_on_failed_step = true;
  policy.draw_unwanted = false;
  policy.output = output;
  return policy;
}

wobble::Viewer cloth_viewer(const wobble::ViewerSettings& settings = wobble::ViewerSettings()) {
  return wobble::Viewer(wobble::make_builtin_scene("cloth"), settings,
                        wobble::builtin_scene_names());
}

TEST(FrameLoop, OneStepAFrameDrawsAndReadsOnlyTheFramesAnOutputWants) {
  wobble::Viewer viewer = cloth_viewer();
  PlayedHost host;
  EveryThird output;
  wobble::FrameMeters meters;
  for (int frame = 0; frame < 7; ++frame)
    draw_frame(viewer, host, meters, headless_policy(&output), 1.0f);
  EXPECT_EQ(viewer.session().simulation().steps_taken(), 7);
  EXPECT_EQ(output.taken, (std::vector<long>{3, 6}));
  EXPECT_EQ(host.bound, (std::vector<long>{3, 6})) << "the others are laid out, not drawn";
  EXPECT_EQ(host.read, (std::vector<long>{3, 6}));
  EXPECT_EQ(host.begun, 0) << "no ImGui, no platform frame";
  EXPECT_EQ(host.title, "Wobble: cloth");
  EXPECT_EQ(meters.frames, 7);
}

TEST(FrameLoop, AFailedStepEndsARunThatStopsOnOneNamingTheFrame) {
  wobble::ViewerSettings settings;
  // At frame 2, fling a corner 100 km: far beyond the cloth's jump limit.
  settings.drags = {wobble::parse_drag("0:1e5,0,0@2-2", 100)};
  wobble::Viewer viewer = cloth_viewer(settings);
  PlayedHost host;
  wobble::FrameMeters meters;
  const wobble::FramePolicy policy = headless_policy(nullptr);
  draw_frame(viewer, host, meters, policy, 1.0f);
  try {
    draw_frame(viewer, host, meters, policy, 1.0f);
    FAIL() << "the failed step should end the run";
  } catch (const std::runtime_error& error) {
    const std::string what = error.what();
    EXPECT_EQ(what.rfind("frame 2: ", 0), 0u) << what;
    EXPECT_NE(what.find("rolled back"), std::string::npos) << what;
  }
  // A run that goes on (the page) pauses there instead.
  wobble::Viewer page = cloth_viewer(settings);
  wobble::FramePolicy going_on = policy;
  going_on.stop_on_failed_step = false;
  for (int frame = 0; frame < 3; ++frame)
    draw_frame(page, host, meters, going_on, 1.0f);
  EXPECT_TRUE(page.panel().paused());
  EXPECT_NE(page.session().step_warning(), "");
}

TEST(FrameLoop, BatchesExchangeAndEveryFrameIsDrawnWithTheFilesDroppedOpened) {
  wobble::Viewer viewer = cloth_viewer();
  PlayedHost host;
  wobble::FramePolicy policy;  // the window's and the page's, without ImGui for the test
  policy.ui = wobble::FramePolicy::Ui::none;
  wobble::FrameMeters meters;
  host.dropped = {std::string(WOBBLE_ASSETS_DIR) + "/course/banner.json"};
  const wobble::FrameResult first = draw_frame(viewer, host, meters, policy, 1.0f);
  EXPECT_TRUE(first.new_state);
  EXPECT_TRUE(first.drawn);
  EXPECT_EQ(viewer.session().scene().name, "banner");
  EXPECT_EQ(host.title, "Wobble: banner");
  draw_frame(viewer, host, meters, policy, 1.0f);
  viewer.finish_steps();
  EXPECT_GE(viewer.session().simulation().steps_taken(), 1);
  EXPECT_EQ(host.bound, (std::vector<long>{1, 2}));
  EXPECT_TRUE(host.read.empty()) << "nothing asked for a picture";
}

}  // namespace
