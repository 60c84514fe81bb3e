// The panel's self-collision controls and solver combos clicked through real ImGui (fonts built on
// the CPU, nothing drawn), as a user clicks them: the viewer hands them to the simulation (and to
// the split view's right side); a course scene offers neither. And the contacts colouring of the
// viewer's own shape.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <optional>
#include <string>

#include "app/viewer/viewer.h"
#include "io/load_scene.h"
#include "sim/contact/collider_contact_term.h"
#include "sim/contact/self_contact_term.h"
#include "sim/settings/setting_registry.h"
#include "viewer_panel_fixture.h"

namespace {

using wobble::testing::PanelFixture;

TEST(ViewerPanel, TheSelfCollisionCheckboxTurnsItOnAndOffInTheSimulation) {
  PanelFixture f(wobble::make_builtin_scene("cloth"));
  ASSERT_FALSE(f.viewer.session().simulation().params().self_collision.on);
  EXPECT_FALSE(f.find("thickness (mm)")) << "the thickness shows only when on";
  const std::optional<ImVec2> box = f.find("self-collision");
  ASSERT_TRUE(box) << "the panel offers self-collision";

  f.click(*box);
  EXPECT_TRUE(f.viewer.session().simulation().params().self_collision.on);
  // The checkbox alone keeps the thickness exactly as it was.
  EXPECT_EQ(f.viewer.session().simulation().params().self_collision.thickness, 0.01);
  EXPECT_TRUE(f.viewer.session().stats().self_collision);
  for (int i = 0; i < 3; ++i)
    f.viewer.advance();
  EXPECT_EQ(f.viewer.session().stats().self_contacts,
            f.viewer.session().simulation().term<wobble::SelfContactTerm>()->contact_count());
  EXPECT_TRUE(f.find("thickness (mm)"));

  f.click(*f.find("self-collision"));
  EXPECT_FALSE(f.viewer.session().simulation().params().self_collision.on);
  EXPECT_FALSE(f.viewer.session().stats().self_collision);
}

// While a batch of steps runs on the stepping thread, the checkbox waits in the panel; the
// simulation takes it when the batch is handed over.
TEST(ViewerPanel, TheCheckboxReachesASimulationSteppingOnItsThread) {
  PanelFixture f(wobble::make_builtin_scene("cloth"));
  const std::optional<ImVec2> box = f.find("self-collision");
  ASSERT_TRUE(box);
  f.viewer.session().step_on_thread([] {});
  ASSERT_TRUE(f.viewer.exchange(0.0, 1.0 / 60.0));  // starts a batch
  f.click(*box);
  f.viewer.finish_steps();
  EXPECT_TRUE(f.viewer.session().simulation().params().self_collision.on);
}

// The split view's right side follows the left's environment, self-collision included.
TEST(ViewerPanel, TheSplitViewsRightSideFollowsTheCheckbox) {
  wobble::ViewerSettings settings;
  settings.compare = wobble::parse_compare_settings("iterations=5");
  PanelFixture f(wobble::make_builtin_scene("cloth"), settings);
  ASSERT_NE(f.viewer.session().right_side(), nullptr);
  const std::optional<ImVec2> box = f.find("self-collision");
  ASSERT_TRUE(box);
  f.click(*box);
  f.viewer.advance();
  EXPECT_TRUE(f.viewer.session().right_side()->params().self_collision.on);
  f.click(*f.find("self-collision"));
  f.viewer.advance();
  EXPECT_FALSE(f.viewer.session().right_side()->params().self_collision.on);
}

// A course scene reproduces the course's program, as the command line keeps it (--damping and
// --self-collision are refused for one): self-collision and damping are drawn greyed out, and
// clicking or dragging them changes nothing.
TEST(ViewerPanel, ACourseSceneKeepsSelfCollisionAndDampingOff) {
  PanelFixture f(wobble::load_scene(std::string(WOBBLE_ASSETS_DIR) + "/course/banner.json"));
  ASSERT_EQ(f.viewer.session().simulation().params().gravity_model,
            wobble::GravityModel::force_per_vertex);
  const std::optional<ImVec2> box = f.scroll_to("self-collision");
  ASSERT_TRUE(box) << "drawn, greyed out";
  f.click(*box);
  EXPECT_FALSE(f.viewer.session().simulation().params().self_collision.on);
  const std::optional<ImVec2> damping = f.scroll_to("damping (1/s)");
  ASSERT_TRUE(damping);
  f.drag(*damping, 60.0f);
  EXPECT_EQ(f.viewer.session().simulation().params().damping, 0.0);
}

// Gravity's control is its strength, declared with the other settings: dragged in the panel, it
// changes the strength and keeps the scene's own direction, sideways part included; dragged to
// zero and back, the direction is still the scene's; and the split view's right side follows.
TEST(ViewerPanel, TheGravityDragKeepsTheScenesDirection) {
  wobble::Scene scene = wobble::make_builtin_scene("cloth");
  scene.params.gravity = Eigen::Vector3d(3.0, -4.0, 0.0);  // 5 m/s², tilted
  wobble::ViewerSettings settings;
  settings.compare = wobble::parse_compare_settings("iterations=5");
  PanelFixture f(scene, settings);
  const auto gravity = [&] { return f.viewer.session().simulation().params().gravity; };
  std::optional<ImVec2> control = f.scroll_to("gravity (m/s^2)");
  ASSERT_TRUE(control);
  f.drag(*control, 40.0f);
  const Eigen::Vector3d dragged = gravity();
  EXPECT_GT(dragged.norm(), 5.5) << "dragged right: stronger";
  EXPECT_NEAR(dragged.normalized().dot(Eigen::Vector3d(0.6, -0.8, 0.0)), 1.0, 1e-12);
  f.viewer.advance();
  EXPECT_EQ(f.viewer.session().right_side()->params().gravity, dragged);
  // To zero (the drag stops there), then back up.
  f.drag(*f.scroll_to("gravity (m/s^2)"), -400.0f);
  EXPECT_EQ(gravity().norm(), 0.0);
  f.drag(*f.scroll_to("gravity (m/s^2)"), 40.0f);
  ASSERT_GT(gravity().norm(), 0.0);
  EXPECT_NEAR(gravity().normalized().dot(Eigen::Vector3d(0.6, -0.8, 0.0)), 1.0, 1e-12);
}

// The same clicks and drags on the cloth turn self-collision on and damp it.
TEST(ViewerPanel, TheClothTakesSelfCollisionAndDamping) {
  PanelFixture f(wobble::make_builtin_scene("cloth"));
  const std::optional<ImVec2> box = f.scroll_to("self-collision");
  ASSERT_TRUE(box);
  f.click(*box);
  EXPECT_TRUE(f.viewer.session().simulation().params().self_collision.on);
  const std::optional<ImVec2> damping = f.scroll_to("damping (1/s)");
  ASSERT_TRUE(damping);
  f.drag(*damping, 60.0f);
  EXPECT_GT(f.viewer.session().simulation().params().damping, 0.0);
}

// The solver combo switches the running simulation from the next step on, keeping its state;
// Chebyshev, which applies to local-global only, is greyed out meanwhile.
TEST(ViewerPanel, TheSolverComboSwitchesTheSimulationWhileItRuns) {
  PanelFixture f(wobble::make_builtin_scene("cloth"));
  ASSERT_EQ(f.viewer.session().simulation().params().solver, "local-global");
  EXPECT_EQ(f.viewer.session().stats().solver, "local-global");
  for (int i = 0; i < 5; ++i)
    f.viewer.advance();
  const Eigen::MatrixXd before = f.viewer.session().simulation().positions();
  ASSERT_TRUE(f.choose("solver", "L-BFGS"));
  EXPECT_EQ(f.viewer.session().simulation().params().solver, "lbfgs");
  EXPECT_EQ(f.viewer.session().simulation().steps_taken(), 5);
  EXPECT_EQ(f.viewer.session().simulation().positions(), before) << "the state is kept";
  f.viewer.advance();
  EXPECT_EQ(f.viewer.session().stats().solver, "L-BFGS");

  // Greyed out: a click leaves Chebyshev off.
  const std::optional<ImVec2> chebyshev = f.find("Chebyshev acceleration");
  ASSERT_TRUE(chebyshev);
  f.click(*chebyshev);
  EXPECT_FALSE(f.viewer.session().simulation().params().chebyshev);
  ASSERT_TRUE(f.choose("solver", "local-global"));
  EXPECT_EQ(f.viewer.session().simulation().params().solver, "local-global");
  f.click(*f.find("Chebyshev acceleration"));
  EXPECT_TRUE(f.viewer.session().simulation().params().chebyshev) << "local-global takes it again";
}

// While a batch runs on the stepping thread, the choice waits; the simulation takes it between
// batches, as every panel edit.
TEST(ViewerPanel, TheSolverReachesASimulationSteppingOnItsThread) {
  PanelFixture f(wobble::make_builtin_scene("cloth"));
  f.viewer.session().step_on_thread([] {});
  ASSERT_TRUE(f.viewer.exchange(0.0, 1.0 / 60.0));  // starts a batch
  ASSERT_TRUE(f.choose("solver", "L-BFGS"));
  f.viewer.finish_steps();
  EXPECT_EQ(f.viewer.session().simulation().params().solver, "lbfgs");
  // Restore defaults brings back the scene's own.
  const std::optional<ImVec2> restore = f.find("Restore defaults");
  ASSERT_TRUE(restore);
  f.click(*restore);
  f.viewer.finish_steps();
  EXPECT_EQ(f.viewer.session().simulation().params().solver, "local-global");
}

// The compare section's own combo: the right side's solver, the left's unchanged.
TEST(ViewerPanel, TheRightSolverComboSwitchesTheSplitViewsRightSide) {
  wobble::ViewerSettings settings;
  settings.compare = wobble::parse_compare_settings("solver=lbfgs");
  PanelFixture f(wobble::make_builtin_scene("cloth"), settings);
  ASSERT_NE(f.viewer.session().right_side(), nullptr);
  EXPECT_EQ(f.viewer.session().right_side()->params().solver, "lbfgs");
  f.viewer.advance();
  ASSERT_TRUE(f.choose("solver right", "local-global"));
  f.viewer.advance();
  EXPECT_EQ(f.viewer.session().right_side()->params().solver, "local-global");
  EXPECT_EQ(f.viewer.session().simulation().params().solver, "local-global");
  ASSERT_TRUE(f.choose("solver right", "L-BFGS"));
  f.viewer.advance();
  EXPECT_EQ(f.viewer.session().right_side()->params().solver, "lbfgs");
  EXPECT_EQ(f.viewer.session().simulation().params().solver, "local-global");
}

// A course scene keeps the course's local-global: the combo is there but greyed out.
TEST(ViewerPanel, ACourseSceneKeepsLocalGlobal) {
  PanelFixture f(wobble::load_scene(std::string(WOBBLE_ASSETS_DIR) + "/course/banner.json"));
  EXPECT_TRUE(f.find("solver"));
  EXPECT_FALSE(f.choose("solver", "L-BFGS"));
  EXPECT_EQ(f.viewer.session().simulation().params().solver, "local-global");
}

// The viewer's own copy of the colours, taken between batches as for strain and speed: the
// collider's colour exactly on the vertices the last step held out of the sphere.
TEST(ViewerColors, ContactsColourTheVerticesOnACollider) {
  wobble::Scene scene = wobble::make_builtin_scene("cloth");
  wobble::Collider sphere;
  sphere.type = wobble::ColliderType::sphere;
  sphere.center = scene.network.V.colwise().mean().transpose() - Eigen::Vector3d(0.0, 0.3, 0.0);
  sphere.radius = 0.25;
  scene.params.contact.colliders.push_back(sphere);
  wobble::ViewerSettings settings;
  settings.color_by = wobble::ColorQuantity::contacts;
  wobble::Viewer viewer(std::move(scene), settings, wobble::builtin_scene_names());
  for (int i = 0; i < 40; ++i)
    viewer.advance();
  const std::vector<char>& flags =
      wobble::collider_contact_vertices(viewer.session().simulation().terms());
  const std::vector<float>& colors = viewer.drawing().quantity_colors().vertex_colors();
  ASSERT_EQ(colors.size(), 3 * flags.size());
  ASSERT_GT(viewer.session()
                .simulation()
                .term<wobble::ColliderContactTerm>()
                ->colliders()
                .contact_count(),
            0)
      << "the cloth lies on the sphere";
  int coloured = 0;
  for (std::size_t i = 0; i < flags.size(); ++i) {
    const Eigen::Vector3f color(colors[3 * i], colors[3 * i + 1], colors[3 * i + 2]);
    const Eigen::Vector3f expected =
        flags[i] ? wobble::collider_contact_color() : wobble::contact_free_color();
    coloured += color == wobble::collider_contact_color();
    EXPECT_EQ(color, expected) << i;
  }
  EXPECT_EQ(coloured, viewer.session()
                          .simulation()
                          .term<wobble::ColliderContactTerm>()
                          ->colliders()
                          .contact_count());
}

}  // namespace

namespace {

// The simulated clock is the accepted steps' dt summed: a new dt changes how fast it runs from
// then on, not what it already shows (it read steps × the current dt, so a dt slider moved
// while paused jumped it).
TEST(ViewerPanel, ANewDtLeavesTheSimulatedClockWhereItWas) {
  PanelFixture f(wobble::make_builtin_scene("cloth"));
  for (int i = 0; i < 30; ++i)
    f.viewer.advance();
  const double before = f.viewer.session().stats().simulated_seconds;
  EXPECT_NEAR(before, 30.0 / 60.0, 1e-12);
  const double dt = f.viewer.session().simulation().params().dt;
  const std::optional<ImVec2> slider = f.find("dt (s)");
  ASSERT_TRUE(slider);
  f.drag(*slider, 60.0f);
  const double new_dt = f.viewer.session().simulation().params().dt;
  ASSERT_GT(new_dt, 1.5 * dt) << "the drag changed dt";
  EXPECT_EQ(f.viewer.session().stats().simulated_seconds, before) << "no step, no time";
  f.viewer.advance();
  EXPECT_NEAR(f.viewer.session().stats().simulated_seconds, before + new_dt, 1e-12);
  EXPECT_EQ(f.viewer.session().stats().simulated_seconds, f.viewer.session().simulation().time())
      << "the plots' time axis and the stats agree";
}

}  // namespace

namespace {

// Whether the simulation's last step had the volume term: it reports its inverted tetrahedra.
bool stepped_with_volume_term(const wobble::Simulation& simulation) {
  for (const wobble::TermFigure& figure : simulation.last_step_timing().figures) {
    if (std::string(figure.term) == "volume") return true;
  }
  return false;
}

double volume_setting(const wobble::Simulation& simulation, const char* name) {
  return wobble::setting_value(simulation.params(), name);
}

// A solid's panel offers the volume term's switch and its stiffness (the jelly: on, 2e4 Pa);
// unticked, the next step goes without the term; ticked again, with it.
TEST(ViewerPanel, TheVolumeSwitchTurnsTheTermOffAndOnForAJelly) {
  PanelFixture f(wobble::make_builtin_scene("jelly"));
  f.viewer.advance();
  ASSERT_TRUE(stepped_with_volume_term(f.viewer.session().simulation()));
  const std::optional<ImVec2> box = f.scroll_to("volume term");
  ASSERT_TRUE(box) << "the panel offers the volume term's switch";
  EXPECT_TRUE(f.scroll_to("volume k (Pa)")) << "and its stiffness beside it";

  f.click(*f.scroll_to("volume term"));
  EXPECT_EQ(volume_setting(f.viewer.session().simulation(), "volume"), 0.0);
  EXPECT_EQ(volume_setting(f.viewer.session().simulation(), "volume-stiffness"), 2e4)
      << "kept as it was";
  f.viewer.advance();
  EXPECT_FALSE(stepped_with_volume_term(f.viewer.session().simulation()));

  f.click(*f.scroll_to("volume term"));
  EXPECT_EQ(volume_setting(f.viewer.session().simulation(), "volume"), 1.0);
  f.viewer.advance();
  EXPECT_TRUE(stepped_with_volume_term(f.viewer.session().simulation()));
}

// The stiffness is dragged by a factor a pixel, as k is, and reaches the simulation.
TEST(ViewerPanel, TheVolumeStiffnessDragReachesTheSimulation) {
  PanelFixture f(wobble::make_builtin_scene("jelly"));
  const std::optional<ImVec2> drag = f.scroll_to("volume k (Pa)");
  ASSERT_TRUE(drag);
  f.drag(*drag, 60.0f);  // 1% a pixel: 1.8 times
  const double stiffness = volume_setting(f.viewer.session().simulation(), "volume-stiffness");
  EXPECT_GT(stiffness, 1.5 * 2e4);
  EXPECT_LE(stiffness, 1e6);
  f.viewer.advance();
  EXPECT_TRUE(stepped_with_volume_term(f.viewer.session().simulation()));
}

// A surface without tetrahedra (the cloth, the course's banner) shows neither, and its settings
// keep the term off.
TEST(ViewerPanel, ASurfaceOffersNoVolumeTerm) {
  {
    PanelFixture cloth(wobble::make_builtin_scene("cloth"));
    EXPECT_TRUE(cloth.find("iterations"));
    EXPECT_FALSE(cloth.scroll_to("volume term"));
    EXPECT_FALSE(cloth.find("volume k (Pa)"));
    EXPECT_EQ(volume_setting(cloth.viewer.session().simulation(), "volume"), 0.0);
  }
  PanelFixture course(wobble::load_scene(std::string(WOBBLE_ASSETS_DIR) + "/course/banner.json"));
  EXPECT_FALSE(course.scroll_to("volume term"));
  EXPECT_EQ(volume_setting(course.viewer.session().simulation(), "volume"), 0.0);
}

// Each side of the split view has its own switch: the jelly with the term on the left and
// without it on the right (--compare volume=off), and the right side's switch turns it on there
// alone.
TEST(ViewerPanel, EachSideOfTheSplitViewHasItsOwnVolumeSwitch) {
  wobble::ViewerSettings settings;
  settings.compare = wobble::parse_compare_settings("volume=off");
  PanelFixture f(wobble::make_builtin_scene("jelly"), settings);
  ASSERT_NE(f.viewer.session().right_side(), nullptr);
  f.viewer.advance();
  EXPECT_TRUE(stepped_with_volume_term(f.viewer.session().simulation()));
  EXPECT_FALSE(stepped_with_volume_term(*f.viewer.session().right_side()));
  const std::optional<ImVec2> right = f.scroll_to("volume term right");
  ASSERT_TRUE(right) << "the right side's own switch";
  EXPECT_TRUE(f.scroll_to("volume k (Pa) right"));
  f.click(*right);
  f.viewer.advance();
  EXPECT_EQ(wobble::setting_value(f.viewer.session().right_side()->params(), "volume"), 1.0);
  EXPECT_TRUE(stepped_with_volume_term(*f.viewer.session().right_side()));
  EXPECT_TRUE(stepped_with_volume_term(f.viewer.session().simulation())) << "the left side kept it";
}

}  // namespace
