// New simulation settings, each declared once (the SettingRegistrations below, beside the term
// that reads them: a number and a switch, declared as the built-in ones are), reach every way a
// user sets or reads one: the command line, scene files (read and written), --compare's two
// sides, the page's address, the panel's controls on both sides, --stats, and
// Simulation::apply, which does only what its cost says. Its own program, so that the settings
// show in no other test's --help or messages.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "app/cli/command_line.h"
#include "app/cli/scene_catalog.h"
#include "app/headless/run_headless.h"
#include "app/viewer/side_settings.h"
#include "app/web/page_arguments.h"
#include "io/load_scene.h"
#include "io/write_wobble_scene.h"
#include "sim/input_error.h"
#include "sim/settings/setting_registry.h"
#include "sim/shapes/builtin_scenes.h"
#include "sim/simulation.h"
#include "sim/terms/term_registry.h"
#include "viewer_panel_fixture.h"

namespace {

using wobble::setting_value;
using wobble::SimulationParams;

// The setting: air drag c (1/s), a force −c·m·v on every vertex, computed from the step's
// velocity. Off (no term at all) at its default 0.
const wobble::SettingRegistration air_drag{{"test-air-drag",
                                            "air drag",
                                            "Air drag on every vertex, as a share of its momentum",
                                            {0.0, 50.0, "1/s"},
                                            0.0,
                                            wobble::SettingCost::terms}};

// The switch: still air, no drag whatever its value. Off by default.
const wobble::SettingRegistration still_air{{"test-still-air",
                                             "still air",
                                             "No air drag, whatever its value",
                                             {0.0, 1.0, ""},
                                             0.0,
                                             wobble::SettingCost::terms,
                                             /*log_scale=*/false,
                                             /*solids_only=*/false,
                                             wobble::SettingType::toggle}};

class AirDrag : public wobble::StepTerm {
 public:
  explicit AirDrag(double drag) : drag_(drag) {}
  const char* name() const override { return "air drag"; }
  void add_forces(const wobble::StepContext& step, Eigen::MatrixXd& fext) override {
    const Eigen::MatrixXd velocity = (step.current - step.previous) / step.dt;
    fext -= drag_ * (step.rest.m.asDiagonal() * velocity);
  }

 private:
  double drag_;
};

std::unique_ptr<wobble::StepTerm> make_air_drag(const wobble::TermSetup& setup) {
  const double drag = setting_value(setup.params, "test-air-drag");
  if (drag == 0.0 || setting_value(setup.params, "test-still-air") != 0.0) return nullptr;
  return std::make_unique<AirDrag>(drag);
}

const wobble::TermRegistration air_drag_term{"air drag", make_air_drag};

std::optional<wobble::CommandLine> parse(std::vector<const char*> args, std::ostream& out) {
  args.insert(args.begin(), "wobble");
  return wobble::parse_command_line(static_cast<int>(args.size()), args.data(), out);
}

std::string refusal(std::vector<const char*> args) {
  std::ostringstream out;
  try {
    parse(std::move(args), out);
  } catch (const wobble::InputError& error) {
    return error.what();
  }
  return "";
}

// How far the cloth's lowest vertex fell in `steps` steps (m).
double fall(wobble::Simulation& simulation, int steps) {
  const double start = simulation.positions().col(1).minCoeff();
  for (int i = 0; i < steps; ++i)
    simulation.step();
  return start - simulation.positions().col(1).minCoeff();
}

// The setting's value is what the simulation does: drag slows the free fall.
TEST(AddedSetting, SimulationApplyBuildsTheTermAgainWithoutRefactorizing) {
  wobble::Scene scene = wobble::make_builtin_scene("cloth");
  wobble::Simulation still(scene.network, {}, scene.params);
  wobble::Simulation dragged(scene.network, {}, scene.params);
  EXPECT_EQ(setting_value(dragged.params(), "test-air-drag"), 0.0) << "its default";
  SimulationParams wanted = dragged.params();
  wanted.added_settings["test-air-drag"] = 20.0;
  const int factorizations = dragged.numeric_factorizations();
  dragged.apply(wanted);
  EXPECT_EQ(dragged.numeric_factorizations(), factorizations) << "its cost is the terms only";
  EXPECT_EQ(setting_value(dragged.params(), "test-air-drag"), 20.0);
  const double free_fall = fall(still, 30), slowed = fall(dragged, 30);
  EXPECT_LT(slowed, 0.8 * free_fall);

  // Out of its range: refused, naming it, and nothing changes.
  wanted.added_settings["test-air-drag"] = 60.0;
  try {
    dragged.apply(wanted);
    ADD_FAILURE() << "60 /s was accepted";
  } catch (const wobble::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("test-air-drag"), std::string::npos) << error.what();
  }
  EXPECT_EQ(setting_value(dragged.params(), "test-air-drag"), 20.0);
}

TEST(AddedSetting, TheCommandLineTakesItAndRefusesABadValue) {
  std::ostringstream help;
  EXPECT_FALSE(parse({"--help"}, help));
  EXPECT_NE(help.str().find("--test-air-drag"), std::string::npos) << help.str();

  std::ostringstream out;
  const std::optional<wobble::CommandLine> command = parse({"--test-air-drag", "2.5"}, out);
  ASSERT_TRUE(command);
  const SimulationParams params =
      command->settings.applied_to(wobble::make_builtin_scene("cloth").params);
  EXPECT_EQ(setting_value(params, "test-air-drag"), 2.5);

  EXPECT_EQ(refusal({"--test-air-drag", "abc"}),
            "--test-air-drag: expected a number within the limits 0 to 50 1/s, got 'abc'");
  EXPECT_EQ(refusal({"--test-air-drag", "51"}),
            "--test-air-drag: expected a number within the limits 0 to 50 1/s, got '51'");
  // Given both ways for the left side: which was meant?
  EXPECT_EQ(refusal({"--test-air-drag", "1", "--compare", "test-air-drag=2,test-air-drag=3"}),
            "--test-air-drag, --compare: both set the left side's test-air-drag, expected one of "
            "them");
}

TEST(AddedSetting, CompareSetsEachSide) {
  const wobble::CompareSettings both =
      wobble::parse_compare_settings("test-air-drag=1,iterations=5,test-air-drag=4");
  const SimulationParams scene = wobble::make_builtin_scene("cloth").params;
  EXPECT_EQ(setting_value(both.left.applied_to(scene), "test-air-drag"), 1.0);
  EXPECT_EQ(setting_value(both.applied_to(scene), "test-air-drag"), 4.0);
  try {
    wobble::parse_compare_settings("test-air-drag=-1");
    ADD_FAILURE() << "-1 was accepted";
  } catch (const wobble::InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "--compare: test-air-drag: expected a number within the limits 0 to 50 1/s, got "
              "'-1'");
  }
}

TEST(AddedSetting, SceneFilesReadAndWriteIt) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("wobble_added_setting_" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  const std::string path = (folder / "drag.json").string();
  std::ofstream(path) << R"({"mesh": {"generator": "cloth", "resolution": 8},
                             "simulation": {"test_air_drag": 3.5}})";
  wobble::Scene scene = wobble::load_scene(path);
  EXPECT_EQ(setting_value(scene.params, "test-air-drag"), 3.5);

  // Saved and read back.
  const std::string saved = (folder / "saved.json").string();
  wobble::write_wobble_scene(saved, scene);
  EXPECT_EQ(setting_value(wobble::load_scene(saved).params, "test-air-drag"), 3.5);

  std::ofstream(path) << R"({"mesh": {"generator": "cloth", "resolution": 8},
                             "simulation": {"test_air_drag": 99}})";
  try {
    wobble::load_scene(path);
    ADD_FAILURE() << "99 /s was accepted";
  } catch (const wobble::InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("test_air_drag"), std::string::npos) << message;
  }
  std::filesystem::remove_all(folder);
}

TEST(AddedSetting, StatsReportIt) {
  std::ostringstream help;
  const std::optional<wobble::CommandLine> command =
      parse({"cloth", "--headless", "--frames", "3", "--stats", "--test-air-drag", "7"}, help);
  ASSERT_TRUE(command);
  std::ostringstream out, progress;
  ASSERT_EQ(wobble::run_headless(*command, out, progress), 0);
  const std::string text = out.str();
  const nlohmann::json stats = nlohmann::json::parse(text.substr(text.rfind('{')));
  EXPECT_EQ(stats.at("test_air_drag").get<double>(), 7.0);
}

// The panel draws a slider for it on each side; dragging one reaches that side's simulation.
TEST(AddedSetting, ThePanelSlidersSetEachSide) {
  wobble::ViewerSettings settings;
  settings.compare = wobble::parse_compare_settings("test-air-drag=2");
  wobble::testing::PanelFixture f(wobble::make_builtin_scene("cloth"), settings);
  ASSERT_TRUE(f.viewer.session().right_side());
  EXPECT_EQ(setting_value(f.viewer.session().right_side()->params(), "test-air-drag"), 2.0);

  const std::optional<ImVec2> left = f.scroll_to("air drag (1/s)");
  ASSERT_TRUE(left) << "the left side's slider";
  f.drag(*left, 80.0f);
  const double dragged = setting_value(f.viewer.session().simulation().params(), "test-air-drag");
  EXPECT_GT(dragged, 0.0);
  EXPECT_EQ(setting_value(f.viewer.session().right_side()->params(), "test-air-drag"), 2.0)
      << "each side keeps its own";

  const std::optional<ImVec2> right = f.scroll_to("air drag (1/s) right");
  ASSERT_TRUE(right) << "the right side's slider";
  f.drag(*right, 80.0f);
  EXPECT_GT(setting_value(f.viewer.session().right_side()->params(), "test-air-drag"), 2.0);
  EXPECT_EQ(setting_value(f.viewer.session().simulation().params(), "test-air-drag"), dragged);
}

// The sliders' translation keeps what they still show: an untouched panel changes nothing.
TEST(AddedSetting, UntouchedSlidersChangeNothing) {
  SimulationParams params = wobble::make_builtin_scene("cloth").params;
  params.dt = 1.0 / 60.0;                        // not a float
  params.added_settings["test-air-drag"] = 0.1;  // nor this
  wobble::SideSliders sliders;
  wobble::show_settings(params, sliders);
  ASSERT_TRUE(sliders.control("test-air-drag"));
  ASSERT_TRUE(sliders.control("test-still-air"));
  const SimulationParams back = wobble::settings_from_sliders(params, sliders, 100);
  EXPECT_EQ(back.dt, params.dt);
  EXPECT_EQ(back.added_settings, params.added_settings);
  EXPECT_EQ(back.k, params.k);
}

// The switch, declared as a built-in one is, the same way round: each place a user meets it.
TEST(AddedSwitch, TheCommandLineAndSimulationApplyTakeIt) {
  std::ostringstream help;
  EXPECT_FALSE(parse({"--help"}, help));
  EXPECT_NE(help.str().find("--test-still-air "), std::string::npos) << help.str();
  std::ostringstream out;
  const std::optional<wobble::CommandLine> command =
      parse({"--test-air-drag", "20", "--test-still-air"}, out);
  ASSERT_TRUE(command);
  EXPECT_EQ(command->settings.toggle("test-still-air"), true);
  const wobble::Scene scene = wobble::make_builtin_scene("cloth");
  const SimulationParams params = command->settings.applied_to(scene.params);
  EXPECT_EQ(setting_value(params, "test-still-air"), 1.0);
  // Still air: no drag, the free fall of no drag at all.
  wobble::Simulation still(scene.network, {}, params), plain(scene.network, {}, scene.params);
  EXPECT_EQ(fall(still, 20), fall(plain, 20));
  // Turned off through Simulation::apply: the drag is back.
  const int factorizations = still.numeric_factorizations();
  still.apply(wobble::with_setting(still.params(), "test-still-air", false));
  EXPECT_EQ(still.numeric_factorizations(), factorizations) << "its cost is the terms only";
  EXPECT_LT(fall(still, 20), fall(plain, 20));
}

TEST(AddedSwitch, CompareSetsEachSide) {
  const wobble::CompareSettings both =
      wobble::parse_compare_settings("test-still-air=on,test-still-air=off");
  const SimulationParams scene = wobble::make_builtin_scene("cloth").params;
  EXPECT_EQ(setting_value(both.left.applied_to(scene), "test-still-air"), 1.0);
  EXPECT_EQ(setting_value(both.applied_to(scene), "test-still-air"), 0.0);
  try {
    wobble::parse_compare_settings("test-still-air=maybe");
    ADD_FAILURE() << "maybe was accepted";
  } catch (const wobble::InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "--compare: test-still-air: expected on or off, got 'maybe'");
  }
}

TEST(AddedSwitch, SceneFilesReadAndWriteIt) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("wobble_added_switch_" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  const std::string path = (folder / "still.json").string();
  std::ofstream(path) << R"({"mesh": {"generator": "cloth", "resolution": 8},
                             "simulation": {"test_still_air": true}})";
  wobble::Scene scene = wobble::load_scene(path);
  EXPECT_EQ(setting_value(scene.params, "test-still-air"), 1.0);
  const std::string saved = (folder / "saved.json").string();
  wobble::write_wobble_scene(saved, scene);
  std::ifstream in(saved);
  const nlohmann::json written = nlohmann::json::parse(in);
  EXPECT_EQ(written.at("simulation").at("test_still_air"), true);
  EXPECT_EQ(setting_value(wobble::load_scene(saved).params, "test-still-air"), 1.0);

  std::ofstream(path) << R"({"mesh": {"generator": "cloth", "resolution": 8},
                             "simulation": {"test_still_air": 3}})";
  try {
    wobble::load_scene(path);
    ADD_FAILURE() << "3 was accepted";
  } catch (const wobble::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("test_still_air"), std::string::npos) << error.what();
  }
  std::filesystem::remove_all(folder);
}

// The page's address takes it as a switch, and the page's link gives it back.
TEST(AddedSwitch, ThePageAddressTakesItAndItsLinkGivesItBack) {
  const std::vector<std::string> catalog = {"cloth"};
  const wobble::PageRequest request =
      wobble::read_page_address("?scene=cloth&test-still-air&test-air-drag=3", catalog);
  EXPECT_TRUE(request.refusals.empty());
  EXPECT_EQ(request.arguments, (std::vector<std::string>{"wobble", "--test-still-air",
                                                         "--test-air-drag", "3", "--", "cloth"}));
  const SimulationParams opened = wobble::make_builtin_scene("cloth").params;
  SimulationParams now = wobble::with_setting(opened, "test-still-air", true);
  now = wobble::with_setting(now, "test-air-drag", 3.0);
  EXPECT_EQ(wobble::page_link_query("cloth", opened, now),
            "?scene=cloth&test-air-drag=3&test-still-air");
  EXPECT_EQ(wobble::page_link_losses(now, opened), (std::vector<std::string>{"still air off"}));
}

TEST(AddedSwitch, StatsReportIt) {
  std::ostringstream help;
  const std::optional<wobble::CommandLine> command =
      parse({"cloth", "--headless", "--frames", "2", "--stats", "--test-still-air"}, help);
  ASSERT_TRUE(command);
  std::ostringstream out, progress;
  ASSERT_EQ(wobble::run_headless(*command, out, progress), 0);
  const std::string text = out.str();
  const nlohmann::json stats = nlohmann::json::parse(text.substr(text.rfind('{')));
  EXPECT_EQ(stats.at("test_still_air"), true);
}

// A checkbox on each side; a click reaches that side's simulation alone.
TEST(AddedSwitch, ThePanelCheckboxesSetEachSide) {
  wobble::ViewerSettings settings;
  settings.compare = wobble::parse_compare_settings("iterations=5");
  wobble::testing::PanelFixture f(wobble::make_builtin_scene("cloth"), settings);
  ASSERT_TRUE(f.viewer.session().right_side());
  const std::optional<ImVec2> left = f.scroll_to("still air");
  ASSERT_TRUE(left) << "the left side's checkbox";
  f.click(*left);
  EXPECT_EQ(setting_value(f.viewer.session().simulation().params(), "test-still-air"), 1.0);
  EXPECT_EQ(setting_value(f.viewer.session().right_side()->params(), "test-still-air"), 0.0)
      << "each side keeps its own";
  const std::optional<ImVec2> right = f.scroll_to("still air right");
  ASSERT_TRUE(right) << "the right side's checkbox";
  f.click(*right);
  EXPECT_EQ(setting_value(f.viewer.session().right_side()->params(), "test-still-air"), 1.0);
}

}  // namespace
