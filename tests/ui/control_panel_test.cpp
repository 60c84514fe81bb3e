// The control panel through real ImGui (fonts built on the CPU, nothing drawn), as a user works
// it: at a laptop's 1280 × 720 every section and the stats are in reach without overlap, a
// section opened or closed leaves the list where it was, and the drags over decades move by
// 1% a pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include "panel_driver.h"
#include "ui/log_drag.h"

namespace {

using wobble::PanelSettings;
using wobble::SideSliders;
using wobble::testing::PanelDriver;

// A side's control of the setting `name`.
wobble::SettingControl& control(SideSliders& side, const char* name) {
  wobble::SettingControl* found = side.control(name);
  if (found == nullptr) throw std::logic_error(std::string("no control ") + name);
  return *found;
}

// Every row the panel can show at once: the split view's, self-collision's and its thickness, the
// colliders' and friction, the wind's speed and heading, the solver combos, a warning, a
// recording and two notes.
void show_everything(PanelDriver& panel) {
  panel.stats.solver = "local-global";
  panel.settings.split = true;
  wobble::SimulationParams environment;
  environment.self_collision.on = true;
  environment.contact.colliders.emplace_back();  // the ground
  environment.contact.friction = 0.5;
  environment.wind.velocity = Eigen::Vector3d(0.0, 0.0, 5.0);  // 5 m/s towards +z
  panel.show_environment(environment);
  panel.stats.has_colliders = true;
  panel.stats.self_collision = true;
  panel.stats.warning = "the step diverged: positions over 1e6 m; paused";
  panel.stats.recording = "wobble-cloth-frames-0001/ (12 frames)";
  panel.stats.notes = {"vertex masses from the Voronoi areas", "saved ./wobble-cloth-0001.png"};
}

struct Display {
  float width, height, scale;
};

class PanelFits : public ::testing::TestWithParam<Display> {};

TEST_P(PanelFits, TheStatsStayInViewAndEveryRowIsReachable) {
  const Display display = GetParam();
  PanelDriver panel(display.width, display.height, display.scale);
  show_everything(panel);
  panel.settle();
  const ImGuiWindow* window = PanelDriver::panel();
  ASSERT_NE(window, nullptr);
  EXPECT_GE(window->Pos.y, 0.0f);
  EXPECT_LE(window->Pos.y + window->Size.y, display.height) << "the panel's bottom is off screen";
  const ImGuiWindow* list = PanelDriver::child("sections");
  const ImGuiWindow* stats = PanelDriver::child("stats");
  ASSERT_NE(list, nullptr) << "the sections scroll in a list of their own";
  ASSERT_NE(stats, nullptr) << "the stats are pinned under the list";
  // The stats: inside the panel, under the list, all their lines shown.
  EXPECT_GE(stats->Pos.y, list->Pos.y + list->Size.y);
  EXPECT_LE(stats->Pos.y + stats->Size.y, window->Pos.y + window->Size.y);
  EXPECT_LE(stats->ContentSize.y, stats->Size.y + 0.5f) << "a stats line is cut off";
  EXPECT_EQ(stats->ScrollMax.y, 0.0f);

  // Every row, scrolled to where it is: in the list, above the stats.
  const char* const rows[] = {"scene",
                              "##open",
                              "real time",
                              "simulation",
                              "k (N/m)",
                              "dt (s)",
                              "iterations",
                              "solver",
                              "Chebyshev acceleration",
                              "Restore defaults",
                              "environment",
                              "damping (1/s)",
                              "friction",
                              "wind (m/s)",
                              "wind heading",
                              "colliders",
                              "self-collision",
                              "thickness (mm)",
                              "view",
                              "surface",
                              "springs",
                              "colour by",
                              "UI scale",
                              "instruments",
                              "convergence",
                              "compare",
                              "split view: right side",
                              "k (N/m) right",
                              "dt (s) right",
                              "iterations right",
                              "solver right",
                              "Chebyshev acceleration right",
                              "timings",
                              "scene notes"};
  panel.scroll_to(/*bottom=*/false);
  const ImGuiWindow* scrolled = PanelDriver::child("sections");
  for (const char* row : rows) {
    std::optional<ImVec2> at = panel.find(row);
    // Down the list a notch at a time until it shows.
    for (int notch = 0; !at && notch < 40; ++notch) {
      const ImVec2 over(scrolled->Pos.x + 20.0f, scrolled->Pos.y + 20.0f);
      panel.frame(over, false, -1.0f);
      at = panel.find(row);
    }
    ASSERT_TRUE(at) << row << " cannot be reached";
    EXPECT_LT(at->y, stats->Pos.y) << row;
    panel.scroll_to(/*bottom=*/false);
  }
}

INSTANTIATE_TEST_SUITE_P(Displays, PanelFits,
                         ::testing::Values(Display{1280.0f, 720.0f, 1.0f},
                                           Display{1280.0f, 720.0f, 1.5f},
                                           Display{1920.0f, 1080.0f, 1.0f},
                                           Display{640.0f, 400.0f, 1.0f}));

// On a tall display the panel is as tall as its contents: no blank under the last section.
TEST(ControlPanel, OnATallDisplayThePanelFitsItsContents) {
  PanelDriver panel(1920.0f, 1080.0f, 1.0f);
  panel.settle();
  const ImGuiWindow* list = PanelDriver::child("sections");
  ASSERT_NE(list, nullptr);
  EXPECT_EQ(list->ScrollMax.y, 0.0f) << "everything fits at 1080 rows";
  EXPECT_LT(PanelDriver::panel()->Size.y, 1000.0f);
  EXPECT_GE(list->Size.y + 1.0f, list->ContentSize.y);
}

// The panel's margin is 10 points: at its margin when the scale changes (the page's pixel ratio
// or the browser's zoom changing live, the UI scale), it keeps 10 points from the corner; moved
// by the user, it stays where it was put.
TEST(ControlPanel, ThePanelAtItsMarginKeepsItWhenTheScaleChanges) {
  PanelDriver panel(2560.0f, 1440.0f, 1.0f);
  panel.settle();
  ImGuiWindow* window = PanelDriver::panel();
  ASSERT_EQ(window->Pos.x, 10.0f);
  ASSERT_EQ(window->Pos.y, 10.0f);
  // The panel's corner once drawn at `scale`.
  const auto corner_at = [&](float scale) {
    panel.set_scale(scale);
    panel.settle();
    return std::make_pair(window->Pos.x, window->Pos.y);
  };
  EXPECT_EQ(corner_at(2.0f), std::make_pair(20.0f, 20.0f));
  // ImGui keeps a window's position in whole pixels.
  EXPECT_EQ(corner_at(1.25f), std::make_pair(12.0f, 12.0f));
  EXPECT_EQ(corner_at(2.0f), std::make_pair(20.0f, 20.0f));
  // Dragged by its title bar, then the scale changes: it stays.
  const ImVec2 title(window->Pos.x + 100.0f, window->Pos.y + 5.0f);
  panel.frame(title);
  panel.frame(title, true);
  panel.frame(ImVec2(title.x + 200.0f, title.y + 50.0f), true);
  panel.frame(ImVec2(title.x + 200.0f, title.y + 50.0f), false);
  panel.settle();
  const ImVec2 put = window->Pos;
  ASSERT_NE(put.x, 20.0f);
  EXPECT_EQ(corner_at(1.0f), std::make_pair(put.x, put.y));
}

// Scrolled to the bottom at 1280 × 720, a section closed and opened again stays under the mouse,
// and so does every row above it.
TEST(ControlPanel, ASectionOpenedOrClosedLeavesTheListWhereItWas) {
  PanelDriver panel(1280.0f, 720.0f, 1.0f);
  show_everything(panel);
  panel.settle();
  const float bottom = panel.scroll_to(/*bottom=*/true);
  ASSERT_GT(bottom, 0.0f) << "the list scrolls at 720 rows";
  const std::optional<ImVec2> header = panel.find("view");
  const std::optional<ImVec2> above = panel.find("self-collision");
  ASSERT_TRUE(header && above);
  const std::optional<ImVec2> below = panel.find("instruments");
  ASSERT_TRUE(below);

  panel.click(*header);  // closed
  for (int i = 0; i < 3; ++i)
    panel.frame(*header);
  EXPECT_FALSE(panel.find("colour by")) << "the section closed";
  EXPECT_EQ(PanelDriver::child("sections")->Scroll.y, bottom) << "the list scrolled by itself";
  std::optional<ImVec2> now = panel.find("view");
  ASSERT_TRUE(now);
  EXPECT_NEAR(now->y, header->y, 2.0f) << "the header moved from under the mouse";
  now = panel.find("self-collision");
  ASSERT_TRUE(now);
  EXPECT_NEAR(now->y, above->y, 2.0f);
  now = panel.find("instruments");
  ASSERT_TRUE(now);
  EXPECT_LT(now->y, below->y - 50.0f) << "what follows the section moves up";

  panel.click(*header);  // open again
  for (int i = 0; i < 3; ++i)
    panel.frame(*header);
  now = panel.find("view");
  ASSERT_TRUE(now);
  EXPECT_NEAR(now->y, header->y, 2.0f);
  now = panel.find("instruments");
  ASSERT_TRUE(now);
  EXPECT_NEAR(now->y, below->y, 2.0f);

  // Back at the top, the list is as long as its rows again: the blank that held the scroll is
  // gone once it is not needed.
  panel.scroll_to(/*bottom=*/false);
  EXPECT_NEAR(panel.scroll_to(/*bottom=*/true), bottom, 2.0f);
}

// k from 400 N/m: a drag of 60 pixels multiplies it by 1.01⁶⁰ ≈ 1.817 (a slider over its six
// decades took it to 174,166); far enough, it stops at the range's ends. A mouse that moves a
// pixel a frame loses its first 2 to ImGui's drag threshold (a drag starts past 3 pixels).
TEST(ControlPanel, ADragOf60PixelsMovesKByOnePercentAPixel) {
  for (const int steps : {1, 6, 60}) {
    const double counted = steps == 60 ? 58.0 : 60.0;
    PanelDriver panel(1280.0f, 720.0f, 1.0f);
    panel.settle();
    ASSERT_EQ(control(panel.settings, "k").value, 400.0f);
    const std::optional<ImVec2> at = panel.find("k (N/m)");
    ASSERT_TRUE(at);
    panel.drag(*at, 60.0f, steps);
    // Each frame's value is rounded to the 0.1 shown; ImGui keeps the rest for the next frame.
    EXPECT_NEAR(control(panel.settings, "k").value, 400.0 * std::pow(1.01, counted), 0.2)
        << steps << " steps";
    panel.drag(*at, -60.0f, steps);
    EXPECT_NEAR(control(panel.settings, "k").value, 400.0f, 0.2f)
        << "back where it was, " << steps << " steps";
  }
  PanelDriver panel(1280.0f, 720.0f, 1.0f);
  panel.settle();
  const std::optional<ImVec2> at = panel.find("k (N/m)");
  ASSERT_TRUE(at);
  panel.drag(*at, 3000.0f, 30);
  EXPECT_EQ(control(panel.settings, "k").value, control(panel.settings, "k").high);
  panel.drag(*at, -3000.0f, 30);
  EXPECT_EQ(control(panel.settings, "k").value, control(panel.settings, "k").low);
}

// Every quantity over decades moves by the same factor a pixel, each from a value in its range.
TEST(ControlPanel, EveryDragOverDecadesMovesByTheSameFactor) {
  struct Case {
    const char* label;
    float& (*value)(PanelSettings&);
    float start;
  };
  const Case cases[] = {
      {"dt (s)", [](PanelSettings& s) -> float& { return control(s, "dt").value; }, 0.01f},
      {"damping (1/s)",
       [](PanelSettings& s) -> float& { return control(s.environment, "damping").value; }, 0.1f},
      {"thickness (mm)",
       [](PanelSettings& s) -> float& {
         return control(s.environment, "self-collision-thickness").value;
       },
       10.0f},
      {"k (N/m) right", [](PanelSettings& s) -> float& { return control(s.right, "k").value; },
       2000.0f},
      {"dt (s) right", [](PanelSettings& s) -> float& { return control(s.right, "dt").value; },
       0.01f}};
  for (const Case& c : cases) {
    PanelDriver panel(1280.0f, 720.0f, 1.0f);
    show_everything(panel);
    c.value(panel.settings) = c.start;
    panel.settle();
    std::optional<ImVec2> at = panel.find(c.label);
    for (int notch = 0; !at && notch < 40; ++notch) {
      panel.frame(ImVec2(100.0f, 300.0f), false, -1.0f);
      at = panel.find(c.label);
    }
    ASSERT_TRUE(at) << c.label;
    panel.drag(*at, 60.0f);
    // Within the rounding to the digits shown ("%.3f" of 0.18 is 0.3%).
    EXPECT_NEAR(c.value(panel.settings) / c.start, std::pow(1.01, 60.0), 0.006) << c.label;
  }
}

// Ctrl+click types an exact value; the range still holds.
TEST(ControlPanel, CtrlClickTypesAnExactK) {
  PanelDriver panel(1280.0f, 720.0f, 1.0f);
  ImGuiIO& io = ImGui::GetIO();
  io.KeyMap[ImGuiKey_Enter] = 13;
  panel.settle();
  const std::optional<ImVec2> at = panel.find("k (N/m)");
  ASSERT_TRUE(at);
  const auto type = [&](const char* text) {
    io.KeyCtrl = true;
    panel.click(*at);
    io.KeyCtrl = false;
    // The field starts with the value selected: typing replaces it.
    io.AddInputCharactersUTF8(text);
    panel.frame(*at);
    io.KeysDown[13] = true;
    panel.frame(*at);
    io.KeysDown[13] = false;
    panel.frame(*at);
  };
  type("1234.5");
  EXPECT_EQ(control(panel.settings, "k").value, 1234.5f);
  type("5e7");
  EXPECT_EQ(control(panel.settings, "k").value, control(panel.settings, "k").high);
}

// Chebyshev applies to local-global only: with L-BFGS chosen its checkbox, on either side, is
// greyed out and a click leaves it as it was.
TEST(ControlPanel, ChebyshevIsGreyedOutForASolverItDoesNotApplyTo) {
  struct Case {
    const char* checkbox;
    SideSliders& (*side)(PanelSettings&);
  };
  for (const Case c :
       {Case{"Chebyshev acceleration", [](PanelSettings& s) -> SideSliders& { return s; }},
        Case{"Chebyshev acceleration right",
             [](PanelSettings& s) -> SideSliders& { return s.right; }}}) {
    SCOPED_TRACE(c.checkbox);
    PanelDriver panel(1920.0f, 1080.0f, 1.0f);
    show_everything(panel);
    control(c.side(panel.settings), "solver").whole = 1;  // L-BFGS
    panel.settle();
    const std::optional<ImVec2> box = panel.find(c.checkbox);
    ASSERT_TRUE(box);
    panel.click(*box);
    EXPECT_FALSE(control(c.side(panel.settings), "chebyshev").on) << "greyed out";
    control(c.side(panel.settings), "solver").whole = 0;  // local-global
    panel.frame();
    panel.click(*box);
    EXPECT_TRUE(control(c.side(panel.settings), "chebyshev").on);
  }
}

// Without solvers offered, there is no combo.
TEST(ControlPanel, NoSolversOfferedNoCombo) {
  PanelDriver panel(1920.0f, 1080.0f, 1.0f);
  control(panel.settings, "solver").choices.clear();
  panel.settle();
  EXPECT_FALSE(panel.find("solver"));
  EXPECT_TRUE(panel.find("Chebyshev acceleration"));
}

TEST(LogDrag, SpeedMakesAFactorAPixelOverTheRange) {
  // k: six decades, 1% a pixel: ln 1.01 / ln 1e6 of (1e6 − 1) per pixel.
  EXPECT_NEAR(wobble::log_drag_speed(1.0f, 1e6f, "%.1f", 1.01f),
              std::log(1.01) / std::log(1e6) * (1e6 - 1.0), 1e-3);
  // From 0: the range starts at the smallest value shown, 0.001 for "%.3f".
  EXPECT_NEAR(wobble::log_drag_speed(0.0f, 10.0f, "%.3f", 1.01f),
              std::log(1.01) / std::log(1e4) * 10.0, 1e-6);
}

}  // namespace

namespace {

// Every number is dragged, never set by where a click lands: a click on the iterations, gravity,
// friction, wind or the UI scale made the value jump to the click, while k and dt dragged.
TEST(ControlPanel, AClickLeavesANumberAndADragMovesIt) {
  struct Case {
    const char* label;
    float (*value)(const PanelSettings&);
  };
  const Case cases[] = {
      {"iterations",
       [](const PanelSettings& s) { return static_cast<float>(s.control("iterations")->whole); }},
      {"gravity (m/s^2)",
       [](const PanelSettings& s) { return s.environment.control("gravity")->value; }},
      {"friction", [](const PanelSettings& s) { return s.environment.control("friction")->value; }},
      {"wind (m/s)",
       [](const PanelSettings& s) { return s.environment.control("wind-velocity")->value; }},
      {"wind heading",
       [](const PanelSettings& s) { return s.environment.control("wind-velocity")->heading; }},
      {"UI scale", [](const PanelSettings& s) { return s.ui_scale; }}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.label);
    PanelDriver panel(1280.0f, 720.0f, 1.0f);
    show_everything(panel);
    panel.settle();
    std::optional<ImVec2> at = panel.find(c.label);
    for (int notch = 0; !at && notch < 40; ++notch) {
      panel.frame(ImVec2(100.0f, 300.0f), false, -1.0f);
      at = panel.find(c.label);
    }
    ASSERT_TRUE(at);
    const float before = c.value(panel.settings);
    panel.click(ImVec2(at->x + 120.0f, at->y));  // well to the right on the widget
    EXPECT_EQ(c.value(panel.settings), before) << "a click sets nothing";
    panel.drag(ImVec2(at->x + 60.0f, at->y), 40.0f);
    EXPECT_GT(c.value(panel.settings), before) << "a drag to the right raises it";
  }
}

}  // namespace

// A phone's tap, or one click, on the folded panel's title opens it: ImGui's own needs a
// double-click or a hit on its small arrow. A drag of the title still only moves it.
TEST(ControlPanel, AClickOnTheFoldedTitleOpensThePanel) {
  PanelDriver panel(390.0f, 844.0f, 1.0f);
  panel.settle();
  ImGui::SetWindowCollapsed("Wobble", true);
  panel.settle();
  ImGuiWindow* window = PanelDriver::panel();
  ASSERT_TRUE(window->Collapsed);
  const ImVec2 title(window->Pos.x + 0.5f * window->Size.x, window->Pos.y + 5.0f);
  // A drag along the title moves it and leaves it folded.
  panel.frame(title);
  panel.frame(title, true);
  panel.frame(ImVec2(title.x + 30.0f, title.y), true);
  panel.frame(ImVec2(title.x + 30.0f, title.y), false);
  panel.settle();
  EXPECT_TRUE(window->Collapsed) << "a drag does not open it";
  const ImVec2 moved(window->Pos.x + 0.5f * window->Size.x, window->Pos.y + 5.0f);
  panel.frame(moved);
  panel.frame(moved, true);
  panel.frame(moved, false);
  panel.settle();
  EXPECT_FALSE(window->Collapsed) << "one click on the title opens it";
  // Open on a phone-shaped display, it takes at most the upper part, so the scene shows below.
  EXPECT_LE(window->Pos.y + window->Size.y, 0.56f * 844.0f);
}
