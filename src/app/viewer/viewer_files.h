#ifndef WOBBLE_APP_VIEWER_VIEWER_FILES_H
#define WOBBLE_APP_VIEWER_VIEWER_FILES_H

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "app/outputs/video_file.h"
#include "app/viewer/notices.h"
#include "app/viewer/save_and_record.h"
#include "io/missing_texture.h"
#include "io/png_image.h"
#include "sim/shapes/builtin_scenes.h"

namespace wobble {

// The viewer's files, a component of it: what it opens (scene and mesh files typed, dropped or
// picked), what it saves and records (SaveAndRecord: the scene, OBJ, PNG, the record toggle),
// and what it tells the user of them (Notices, on screen for a few seconds, and the panel's
// notes). A file that opens is handed to the viewer's `open` (Viewer::load), a line told to its
// `note` (the panel's notes), as the viewer wires them.
class ViewerFiles {
 public:
  struct Hooks {
    // Load `scene`, opened from `source`; throws, leaving all as it was, when it cannot be shown.
    std::function<void(Scene scene, const std::string& source)> open;
    // A line among the panel's notes.
    std::function<void(const std::string& what)> note;
  };
  // `page`: the page's files (dropped files lie in a folder of the page's making, which what is
  // said of them leaves out; a scene opens without a texture it lacks, noted; no record toggle).
  ViewerFiles(Hooks hooks, bool page);

  // Open a scene or mesh file (dropped on the window, or typed into the panel's "open" field),
  // as load_scene reads it. A file that does not load leaves the current scene running, the
  // reason told, `hidden_folder` (and its '/') taken out of it. Returns whether it loaded.
  bool open_file(const std::string& path, const std::string& hidden_folder = "");
  // Files dropped or picked together: the scene file among them (the last .json) opens, its mesh
  // and texture beside it; with no scene file, the last one. Returns whether it loaded.
  bool open_files(const std::vector<std::string>& paths);

  // Tells the user one line: on screen for a few seconds (while notices show) and among the
  // panel's notes (a page's refused address key, a file written).
  void tell(const std::string& what);
  // On screen only (a scene's wind, a file's notes).
  void post(const std::string& what) { notices_.post(what, notice_clock()); }
  const Notices& notices() const { return notices_; }
  // Draw the notices (the window, the page); headless images never show them, so that they do
  // not depend on the wall clock.
  void show_notices(bool on) { show_notices_ = on; }
  bool notices_shown() const { return show_notices_; }

  // Each file a save writes from then on (F12 or PNG, F11 or OBJ, Ctrl+S or Save scene: the scene
  // and its mesh), as its path: the page offers each as a download.
  void set_written(std::function<void(const std::string& path)> written) {
    save_and_record_.set_written(std::move(written));
  }
  // The window: the panel's "record" (F9) records into new folders in `folder`, `progress`
  // told of each (headless images never record from the panel).
  void record_into(std::string folder, std::ostream& progress) {
    save_and_record_.record_into(std::move(folder), progress);
  }
  // After drawing a frame of `scene` (its name) at `steps` and `time`: the screenshot F12 asked
  // for, and while recording the new state. `read_frame` reads the frame drawn, when `drawn` (a
  // minimized window draws none). What was written, or why not, is told.
  void write_frame(const std::string& scene, long steps, const FrameTime& time, bool drawn,
                   const std::function<RgbaImage()>& read_frame);
  // The scene drawn, before the panel goes over it: a recording of the scene alone reads it now.
  void scene_drawn(const std::function<RgbaImage()>& read_frame) {
    save_and_record_.scene_drawn(read_frame);
  }

  // What the viewer's wiring uses: the save rows, F12/F9, saves.
  SaveAndRecord& saves() { return save_and_record_; }

 private:
  Hooks hooks_;
  bool page_ = false;
  MissingTexture missing_texture_ = MissingTexture::refuse;
  SaveAndRecord save_and_record_;
  Notices notices_;
  bool show_notices_ = false;
};

}  // namespace wobble

#endif
