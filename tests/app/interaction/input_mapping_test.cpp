#include "app/interaction/input_mapping.h"

#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <map>

namespace {

using wobble::MouseGesture;
using wobble::ViewerCommand;

TEST(InputMapping, KeysTheIssueAsksFor) {
  const std::map<int, ViewerCommand> expected = {
      {GLFW_KEY_SPACE, ViewerCommand::toggle_pause},
      {GLFW_KEY_S, ViewerCommand::step_once},
      {GLFW_KEY_R, ViewerCommand::reset},
      {GLFW_KEY_E, ViewerCommand::toggle_wireframe},
      {GLFW_KEY_W, ViewerCommand::toggle_wind},
      {GLFW_KEY_C, ViewerCommand::toggle_colliders},
      {GLFW_KEY_P, ViewerCommand::toggle_points},
      {GLFW_KEY_H, ViewerCommand::toggle_help},
      {GLFW_KEY_F, ViewerCommand::frame_mesh},
      {GLFW_KEY_O, ViewerCommand::default_view},
      {GLFW_KEY_ESCAPE, ViewerCommand::close_overlays},
      {GLFW_KEY_L, ViewerCommand::toggle_springs},
      {GLFW_KEY_V, ViewerCommand::cycle_color_by},
  };
  for (const auto& [key, command] : expected)
    EXPECT_EQ(wobble::command_for_key(key), command) << "key " << key;
  EXPECT_EQ(wobble::command_for_key(GLFW_KEY_Q), ViewerCommand::none);
  // Only Ctrl+Q quits; Esc, with or without Ctrl, never does.
  EXPECT_EQ(wobble::command_for_key(GLFW_KEY_Q, /*control=*/true), ViewerCommand::quit);
  EXPECT_EQ(wobble::command_for_key(GLFW_KEY_ESCAPE, /*control=*/true), ViewerCommand::none);
  EXPECT_EQ(wobble::command_for_key(GLFW_KEY_S, /*control=*/true), ViewerCommand::save_scene);
  EXPECT_EQ(wobble::command_for_key(GLFW_KEY_R, /*control=*/true), ViewerCommand::none);
  EXPECT_EQ(wobble::command_for_key(GLFW_KEY_F9), ViewerCommand::toggle_record);
  for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key)
    EXPECT_NE(wobble::command_for_key(key), ViewerCommand::quit) << "key " << key;
  EXPECT_EQ(wobble::command_for_key(GLFW_KEY_UNKNOWN), ViewerCommand::none);
}

TEST(InputMapping, EveryKeyCommandIsInTheHelp) {
  // Each key with a command appears in the bindings the help overlay lists.
  const std::map<int, std::string> names = {
      {GLFW_KEY_SPACE, "Space"}, {GLFW_KEY_S, "S"}, {GLFW_KEY_R, "R"},     {GLFW_KEY_W, "W"},
      {GLFW_KEY_P, "P"},         {GLFW_KEY_L, "L"}, {GLFW_KEY_H, "H"},     {GLFW_KEY_F, "F"},
      {GLFW_KEY_ESCAPE, "Esc"},  {GLFW_KEY_E, "E"}, {GLFW_KEY_C, "C"},     {GLFW_KEY_V, "V"},
      {GLFW_KEY_G, "G"},         {GLFW_KEY_2, "2"}, {GLFW_KEY_F12, "F12"}, {GLFW_KEY_F11, "F11"},
      {GLFW_KEY_TAB, "Tab"},     {GLFW_KEY_O, "O"}, {GLFW_KEY_F9, "F9"}};
  for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key) {
    if (wobble::command_for_key(key) == ViewerCommand::none) continue;
    ASSERT_TRUE(names.count(key)) << "key " << key << " has a command but no name here";
    bool listed = false;
    for (const wobble::Binding& binding : wobble::viewer_bindings())
      listed = listed || binding.input == names.at(key);
    EXPECT_TRUE(listed) << names.at(key) << " is missing from the help";
  }
  bool ctrl_s = false;
  for (const wobble::Binding& binding : wobble::viewer_bindings())
    ctrl_s = ctrl_s || binding.input == "Ctrl+S";
  EXPECT_TRUE(ctrl_s) << "Ctrl+S is missing from the help";
}

TEST(InputMapping, MouseOverTheUiGoesToTheUiOnly) {
  for (int button : {GLFW_MOUSE_BUTTON_LEFT, GLFW_MOUSE_BUTTON_RIGHT, GLFW_MOUSE_BUTTON_MIDDLE}) {
    for (bool control : {false, true}) {
      EXPECT_EQ(wobble::gesture_for_press(button, control, false, /*over_ui=*/true, true, true),
                MouseGesture::none);
    }
  }
}

TEST(InputMapping, LeftButtonDependsOnWhatIsUnderTheCursor) {
  const int left = GLFW_MOUSE_BUTTON_LEFT;
  EXPECT_EQ(wobble::gesture_for_press(left, false, false, false, true, true),
            MouseGesture::grab_pin);
  EXPECT_EQ(wobble::gesture_for_press(left, false, false, false, false, true),
            MouseGesture::grab_free_vertex);
  EXPECT_EQ(wobble::gesture_for_press(left, false, false, false, false, false),
            MouseGesture::orbit);
  // Ctrl+click toggles a pin on any vertex, and does nothing on empty space.
  EXPECT_EQ(wobble::gesture_for_press(left, true, false, false, true, true),
            MouseGesture::toggle_pin);
  EXPECT_EQ(wobble::gesture_for_press(left, true, false, false, false, true),
            MouseGesture::toggle_pin);
  EXPECT_EQ(wobble::gesture_for_press(left, true, false, false, false, false), MouseGesture::none);
  EXPECT_EQ(wobble::gesture_for_press(left, false, true, false, false, false), MouseGesture::pan);
}

TEST(InputMapping, AltLeftGrabsAColliderOrNothing) {
  const int left = GLFW_MOUSE_BUTTON_LEFT;
  EXPECT_EQ(wobble::gesture_for_press(left, false, false, false, false, false, /*alt=*/true,
                                      /*over_collider=*/true),
            MouseGesture::grab_collider);
  // Even over a pin, Alt means the collider.
  EXPECT_EQ(wobble::gesture_for_press(left, false, false, false, true, true, true, true),
            MouseGesture::grab_collider);
  // A missed Alt+click neither grabs the cloth nor orbits.
  EXPECT_EQ(wobble::gesture_for_press(left, false, false, false, true, true, true, false),
            MouseGesture::none);
  EXPECT_EQ(wobble::gesture_for_press(left, false, false, false, false, false, true, false),
            MouseGesture::none);
  // Without Alt a collider under the cursor changes nothing.
  EXPECT_EQ(wobble::gesture_for_press(left, false, false, false, false, false, false, true),
            MouseGesture::orbit);
  EXPECT_EQ(wobble::gesture_for_press(left, false, false, true, false, false, true, true),
            MouseGesture::none);
}

TEST(InputMapping, RightAndMiddlePan) {
  EXPECT_EQ(wobble::gesture_for_press(GLFW_MOUSE_BUTTON_RIGHT, false, false, false, true, true),
            MouseGesture::pan);
  EXPECT_EQ(wobble::gesture_for_press(GLFW_MOUSE_BUTTON_MIDDLE, false, false, false, false, false),
            MouseGesture::pan);
  EXPECT_EQ(wobble::gesture_for_press(GLFW_MOUSE_BUTTON_4, false, false, false, false, false),
            MouseGesture::none);
}

}  // namespace

// A page's help lists only what works there: not the keys the browser keeps (F12, F11, Ctrl+Q)
// nor recording, and the panel's download buttons in their place; Ctrl+S as the download it is
// there and Ctrl+O, the file chooser (the page keeps both from the browser); everything else as
// the desktop's.
TEST(InputMapping, APagesHelpListsOnlyWhatWorksThere) {
  const std::vector<wobble::Binding> page = wobble::page_bindings();
  const auto action = [&](const std::string& input) -> std::string {
    for (const wobble::Binding& binding : page)
      if (binding.input == input) return binding.action;
    return "";
  };
  for (const char* taken : {"F12", "F11", "F9", "Ctrl+Q"})
    EXPECT_EQ(action(taken), "") << taken;
  EXPECT_NE(action("PNG, OBJ, Save scene"), "");
  EXPECT_NE(action("Ctrl+S / Cmd+S").find("download"), std::string::npos);
  EXPECT_NE(action("Ctrl+O / Cmd+O").find("file chooser"), std::string::npos);
  for (const wobble::Binding& binding : wobble::viewer_bindings()) {
    const std::string& input = binding.input;
    if (input != "F12" && input != "F11" && input != "F9" && input != "Ctrl+Q" &&
        input != "Ctrl+S") {
      EXPECT_EQ(action(input), binding.action) << input;
    }
  }
}
