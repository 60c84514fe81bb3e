#ifndef WOBBLE_APP_VIEWER_SAVE_AND_RECORD_H
#define WOBBLE_APP_VIEWER_SAVE_AND_RECORD_H

#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/interaction/input_mapping.h"
#include "app/viewer/window_recorder.h"
#include "io/png_image.h"
#include "render/camera.h"
#include "sim/scene.h"
#include "sim/simulation.h"
#include "ui/panel_sections.h"

namespace wobble {

// A scene saved by Ctrl+S: what to tell the user, and the file written (empty when it failed).
struct SavedScene {
  std::string message;
  std::string path;
};

// Recording and saving, a component of the viewer: the panel's save rows (Save scene, OBJ, PNG,
// record), F12, F11, Ctrl+S and F9, and the files they write into the working folder, each
// under the next free number (window_saves.h). It owns the record toggle and the recording in
// progress, and the screenshot asked for; it writes the scene and the OBJ when the viewer hands
// it the simulation (between batches), and the window's pictures when the window hands it the
// frame drawn. Each write returns what to tell the user.
class SaveAndRecord {
 public:
  // The UI's side.
  // The panel's save rows (panel_sections.h). It takes PNG and record itself; Save scene and
  // OBJ it returns, for the viewer to carry out on the simulation's side (save_scene,
  // export_obj).
  SaveRowRequests draw_panel_rows();
  // F12 (a screenshot of this frame) and F9 (the record toggle); returns whether it took
  // `command`.
  bool command(ViewerCommand command);
  bool recording() const { return recording_; }
  // Called with each file written from then on (a screenshot, an OBJ, a scene and its mesh):
  // the page offers each as a download.
  void set_written(std::function<void(const std::string& path)> written) {
    written_ = std::move(written);
  }
  // Leave the record toggle out of the panel (the page, which has nowhere to record into).
  void hide_record() { record_offered_ = false; }

  // The simulation's side, once a running batch finished.
  // Ctrl+S: the scene with its pins and settings, and `camera`'s view, as
  // wobble-SCENE-scene-NNNN.json (scene_save.h).
  SavedScene save_scene(const Scene& scene, const Simulation& simulation,
                        const OrbitCamera& camera) const;
  // F11: the simulation's positions as wobble-SCENE-NNNN.obj.
  std::string export_obj(const Scene& scene, const Simulation& simulation) const;
  // The instruments' CSV button: `convergence` (skipped when empty: no step traced yet) and
  // `energy` as wobble-SCENE-convergence-NNNN.csv and wobble-SCENE-energy-NNNN.csv; returns what
  // to tell.
  std::string save_plots(const std::string& scene, const std::string& convergence,
                         const std::string& energy) const;

  // The window's side (headless images never record from the panel).
  // Record into new folders in `folder` from now on, `progress` told of each (window_recorder.h).
  void record_into(std::string folder, std::ostream& progress);
  // After a frame of `scene` is drawn, its state after `steps` steps: the screenshot asked for
  // as wobble-SCENE-NNNN.png, and while recording each new state. `read_frame` reads the frame
  // drawn, when `drawn` (a minimized window draws none). Returns what to tell the user, in
  // order.
  // `time` is the state's simulated time, for a video's frames.
  std::vector<std::string> write_frame(const std::string& scene, long steps, bool drawn,
                                       const std::function<RgbaImage()>& read_frame,
                                       const FrameTime& time = FrameTime());
  // What the record toggle writes from its next start: PNG frames (the default), or a video.
  void set_record_format(std::optional<VideoFormat> video);
  // What a recorded frame shows: the scene alone (the default, for slides), or the whole window.
  void set_record_whole_window(bool whole) { record_whole_window_ = whole; }
  // Called once the scene is drawn and before the panel goes over it: while recording the scene
  // alone, `read_frame` is read then, and write_frame records that picture.
  void scene_drawn(const std::function<RgbaImage()>& read_frame);

 private:
  bool wants_scene_frame() const;
  void record(const std::string& scene, long steps, bool drawn,
              const std::function<RgbaImage()>& read_frame, const FrameTime& time,
              std::vector<std::string>& told);

  bool recording_ = false;            // the record toggle
  bool record_offered_ = true;        // the panel shows the toggle (not in the page)
  int record_format_ = 0;             // the panel's choice: RecordFormat (panel_sections.h)
  bool record_whole_window_ = false;  // the panel's second combo: the scene alone by default
  RgbaImage scene_frame_;             // this frame's scene before the panel (scene_drawn)
  bool screenshot_requested_ = false;
  std::unique_ptr<WindowRecorder> recorder_;  // null: nowhere to record (headless)
  std::function<void(const std::string& path)> written_;
  long recorded_step_ = -1;  // the step count of the last frame recorded
};

}  // namespace wobble

#endif
