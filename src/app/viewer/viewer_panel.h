#ifndef WOBBLE_APP_VIEWER_VIEWER_PANEL_H
#define WOBBLE_APP_VIEWER_VIEWER_PANEL_H

#include <functional>
#include <string>
#include <vector>

#include "app/interaction/input_mapping.h"
#include "app/viewer/quantity_colors.h"
#include "render/renderer.h"
#include "ui/control_panel.h"
#include "ui/panel_sections.h"

namespace wobble {

// The page's own (the panel shows "Open file..." and "Copy link" instead of the path field).
struct PageActions {
  std::function<void()> pick_files;
  std::function<void()> copy_link;
};

// The viewer's panel, a component of it: the settings of the sections the viewer applies itself
// (the scene rows, the play rows, "simulation", "environment", "view"), whether the panel shows
// and where it was drawn, the help and the quit asked for. It draws its window with the parts
// other components own handed in (the save rows, "instruments", "compare"), and says what was
// pressed; the viewer carries that out.
class ViewerPanel {
 public:
  // The settings of the sections the viewer draws and applies itself (the components keep
  // theirs).
  struct Settings : SceneRowSettings,
                    PlaySettings,
                    SimulationSettings,
                    EnvironmentSettings,
                    ViewSettings {};

  // `layers` and `color_by` as the viewer starts; `help` is what H lists (viewer_bindings(), or
  // a page's page_bindings()); `page` the page's buttons (none: the window's path field);
  // `folded`: the panel opens folded to its title bar (a phone's narrow screen).
  ViewerPanel(const ViewLayers& layers, ColorQuantity color_by, std::vector<Binding> help,
              PageActions page, bool folded);

  bool paused() const { return settings_.paused; }
  bool real_time() const { return settings_.real_time; }
  bool help_shown() const { return settings_.show_help; }
  bool quit_requested() const { return quit_; }
  // Tab hides the panel.
  bool shown() const { return shown_; }
  // Shown and not folded to its title bar, when it was last drawn.
  bool open() const { return shown_ && place_.shown; }
  // Where the panel was last drawn (window units); not shown when hidden or folded.
  PanelPlace place() const { return shown_ ? place_ : PanelPlace(); }
  // The layers the view draws, as the checkboxes show them.
  ViewLayers layers() const;
  ColorQuantity color_by() const { return static_cast<ColorQuantity>(settings_.color_by); }
  // A scene without faces, which shows its springs and points unasked.
  bool faceless() const { return faceless_; }
  bool page() const { return settings_.page; }

  // What the viewer's wiring uses.
  Settings& settings() { return settings_; }
  const Settings& settings() const { return settings_; }
  // A key's or a button's command, where it is the panel's own (pause, the layers, the colours,
  // help, Tab, quit). Returns whether it took it.
  bool command(ViewerCommand command);
  // A new scene's shape: springs and vertices shown for one without faces, since there is no
  // surface to see; the layers chosen for meshes with faces come back with the next one.
  void show_shape(bool has_faces);
  // Draw the panel (between ImGui's NewFrame and Render) with the parts other components own in
  // `parts`, its own filled in, the help overlay and `step_warning` (why the last step was
  // rolled back) over the view; returns what was pressed. `scenes` are the picker's; the page's
  // buttons call its actions.
  PanelRequests draw(PanelParts parts, const PanelStats& stats,
                     const std::vector<SceneChoice>& scenes, const std::string& step_warning,
                     float ui_scale);

 private:
  Settings settings_;
  bool shown_ = true;
  PanelPlace place_;  // where draw last drew the panel
  bool quit_ = false;
  bool folded_ = false;  // fold the panel at its first drawing
  // Whether the scene has no faces, and the springs and points layers chosen for scenes with
  // faces while such a scene shows both.
  bool faceless_ = false;
  bool chosen_springs_ = false, chosen_points_ = false;
  std::vector<Binding> help_;
  PageActions page_;
};

}  // namespace wobble

#endif
