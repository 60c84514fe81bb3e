// DrawState, what the viewer draws, on its own and without GL (no renderer: render frames the
// camera and marks the picture, as a frame no one sees): the arrays follow the simulation, a
// paused drag draws the held vertex at its target, and a split view's halves share what the
// panel and the plots leave.
#include "app/viewer/draw_state.h"

#include <gtest/gtest.h>

#include "sim/shapes/builtin_scenes.h"

namespace {

struct DrawFixture {
  DrawFixture()
      : scene(wobble::make_builtin_scene("cloth")),
        simulation(scene.network, scene.pins, scene.params),
        drawing(std::nullopt, std::nullopt, 1.0f) {
    drawing.set_shape(scene, wobble::RgbaImage());
    drawing.update_vertex_arrays(simulation, nullptr, -1, false);
    drawing.view_camera().open(scene.look, scene.network.V, 0.0f);
  }
  wobble::Scene scene;
  wobble::Simulation simulation;
  wobble::DrawState drawing;
};

TEST(DrawState, TheArraysAreTheSimulationsPositionsAndAPausedDragDrawsItsTarget) {
  DrawFixture f;
  f.simulation.step();
  f.drawing.update_vertex_arrays(f.simulation, nullptr, -1, false);
  const std::vector<float>& drawn = f.drawing.drawn_positions();
  ASSERT_EQ(drawn.size(), 3u * f.simulation.positions().rows());
  for (Eigen::Index i = 0; i < f.simulation.positions().rows(); ++i) {
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(drawn[3 * i + k], static_cast<float>(f.simulation.positions()(i, k)));
  }
  const int pin = f.simulation.pinned_vertices().front();
  f.simulation.set_pin_target(pin, Eigen::Vector3d(0.25, 2.0, 0.5));
  f.drawing.update_vertex_arrays(f.simulation, nullptr, pin, /*paused=*/true);
  EXPECT_EQ(f.drawing.drawn_positions()[3 * pin + 1], 2.0f);
  f.drawing.update_vertex_arrays(f.simulation, nullptr, pin, /*paused=*/false);
  EXPECT_EQ(f.drawing.drawn_positions()[3 * pin + 1],
            static_cast<float>(f.simulation.positions()(pin, 1)));
}

TEST(DrawState, SplitHalvesShareWhatThePanelAndPlotsLeaveOrTheWholeWindow) {
  DrawFixture f;
  wobble::PanelPlace panel;
  panel.shown = true;
  panel.x = 0.0f;
  panel.width = 300.0f;
  f.drawing.set_plots_left(1000.0f);
  const wobble::DrawState::SplitArea area = f.drawing.split_area(1280.0f, panel);
  EXPECT_EQ(area.left, 300.0f);
  EXPECT_EQ(area.half, 350.0f);
  // Two halves narrower than a sixth of the window each: the whole window.
  panel.width = 800.0f;
  const wobble::DrawState::SplitArea whole = f.drawing.split_area(1280.0f, panel);
  EXPECT_EQ(whole.left, 0.0f);
  EXPECT_EQ(whole.half, 640.0f);
  const wobble::PointerView picture =
      f.drawing.pointer_view(Eigen::Vector2f(1280.0f, 720.0f), panel, /*split=*/true);
  EXPECT_TRUE(picture.split);
  EXPECT_EQ(picture.size.x(), 640.0f);
}

TEST(DrawState, RenderWithoutARendererFramesTheShapeAndMarksThePicture) {
  DrawFixture f;
  wobble::DrawInputs inputs;
  inputs.width = 1280;
  inputs.height = 720;
  inputs.window = Eigen::Vector2f(1280.0f, 720.0f);
  int marked = 0;
  f.drawing.render(
      inputs, [&](const wobble::PointerView& picture, std::vector<unsigned char>& marks) {
        ++marked;
        EXPECT_EQ(picture.positions, &f.drawing.drawn_positions());
        EXPECT_EQ(marks.size(), static_cast<std::size_t>(f.simulation.positions().rows()));
      });
  EXPECT_EQ(marked, 1);
  EXPECT_GT(f.drawing.camera().distance, 0.0f);
  EXPECT_FALSE(f.drawing.has_renderer());
}

}  // namespace
