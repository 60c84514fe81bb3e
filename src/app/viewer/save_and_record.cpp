// The viewer's files: the scene (Ctrl+S), the positions (F11), the window (F12) and its
// recordings (F9), each under the next free number in the working folder.
#include "app/viewer/save_and_record.h"

#include <exception>
#include <filesystem>
#include <utility>

#include "app/cli/scene_catalog.h"
#include "app/viewer/scene_save.h"
#include "app/viewer/window_saves.h"
#include "io/atomic_file.h"
#include "io/write_obj.h"

namespace wobble {

SaveRowRequests SaveAndRecord::draw_panel_rows() {
  std::string status;
  if (recorder_) status = recorder_->status();
  SaveRowRequests requests =
      draw_save_rows(recording_, record_format_, record_whole_window_, status, record_offered_);
  if (requests.screenshot) command(ViewerCommand::screenshot);
  requests.screenshot = false;  // taken
  return requests;
}

bool SaveAndRecord::command(ViewerCommand command) {
  switch (command) {
    case ViewerCommand::screenshot:
      screenshot_requested_ = true;
      return true;
    case ViewerCommand::toggle_record:
      recording_ = !recording_;
      return true;
    default:
      return false;
  }
}

SavedScene SaveAndRecord::save_scene(const Scene& scene, const Simulation& simulation,
                                     const OrbitCamera& camera) const {
  const std::string path = unused_file_name(".", "wobble-" + scene.name + "-scene", ".json");
  try {
    const Eigen::Vector3d eye = camera_eye(camera).cast<double>();
    save_current_scene(path, scene, simulation,
                       std::make_pair(eye, Eigen::Vector3d(camera.target.cast<double>())));
    if (written_) {
      // The page: both files are downloads, which only a drop brings back into a page.
      const std::string mesh = std::filesystem::path(path).replace_extension(".obj").string();
      written_(mesh);
      written_(path);
      const std::string name = std::filesystem::path(path).filename().string();
      return SavedScene{"downloaded " + name + " and its mesh " +
                            std::filesystem::path(mesh).filename().string() +
                            "; drop both on the page to open the scene again",
                        path};
    }
    return SavedScene{"saved the scene as " + path + " (wobble " + path +
                          " opens it; the scene picker lists it as " + scene_label(path) + ")",
                      path};
  } catch (const std::exception& error) {
    return SavedScene{std::string("saving the scene failed: ") + error.what(), std::string()};
  }
}

std::string SaveAndRecord::export_obj(const Scene& scene, const Simulation& simulation) const {
  const std::string path = unused_file_name(".", "wobble-" + scene.name, ".obj");
  try {
    write_obj(path, simulation.positions(), scene.network.F, scene.network.E);
    if (written_) written_(path);
    return "exported " + path;
  } catch (const std::exception& error) {
    return std::string("export failed: ") + error.what();
  }
}

std::string SaveAndRecord::save_plots(const std::string& scene, const std::string& convergence,
                                      const std::string& energy) const {
  std::string told;
  try {
    for (const auto& [what, text] :
         {std::pair<const char*, const std::string&>("convergence", convergence),
          std::pair<const char*, const std::string&>("energy", energy)}) {
      if (text.empty()) continue;
      const std::string path = unused_file_name(".", "wobble-" + scene + "-" + what, ".csv");
      write_output_file(path, text);
      if (written_) written_(path);
      told += (told.empty() ? "saved the plots as " : " and ") + path;
    }
    return told;
  } catch (const std::exception& error) {
    return std::string("saving the plots failed: ") + error.what();
  }
}

void SaveAndRecord::record_into(std::string folder, std::ostream& progress) {
  recorder_ = std::make_unique<WindowRecorder>(std::move(folder), progress);
}

void SaveAndRecord::set_record_format(std::optional<VideoFormat> video) {
  record_format_ = !video                        ? record_png_frames
                   : *video == VideoFormat::webm ? record_webm_video
                                                 : record_mp4_video;
}

std::vector<std::string> SaveAndRecord::write_frame(const std::string& scene, long steps,
                                                    bool drawn,
                                                    const std::function<RgbaImage()>& read_frame,
                                                    const FrameTime& time) {
  std::vector<std::string> told;
  // What the window shows, panel included.
  if (screenshot_requested_ && drawn) {
    const std::string path = unused_file_name(".", "wobble-" + scene, ".png");
    try {
      write_png(path, read_frame());
      told.push_back("saved " + path);
      if (written_) written_(path);
    } catch (const std::exception& error) {
      told.push_back(std::string("screenshot failed: ") + error.what());
    }
  }
  screenshot_requested_ = false;
  if (recorder_) {
    if (wants_scene_frame() && !scene_frame_.pixels.empty()) {
      // The scene as it was before the panel was drawn over it (scene_drawn). (A frame whose
      // scene was not kept, where no panel was drawn, is what the window shows.)
      record(
          scene, steps, drawn, [this] { return std::move(scene_frame_); }, time, told);
    } else {
      record(scene, steps, drawn, read_frame, time, told);
    }
  }
  scene_frame_ = RgbaImage();
  return told;
}

bool SaveAndRecord::wants_scene_frame() const {
  return recorder_ && recording_ && !record_whole_window_;
}

void SaveAndRecord::scene_drawn(const std::function<RgbaImage()>& read_frame) {
  if (wants_scene_frame()) scene_frame_ = read_frame();
}

void SaveAndRecord::record(const std::string& scene, long steps, bool drawn,
                           const std::function<RgbaImage()>& read_frame, const FrameTime& time,
                           std::vector<std::string>& told) {
  // Each new state drawn while the toggle is on, into a folder or a video of its own.
  if (recording_ && !recorder_->active()) {
    std::optional<VideoFormat> video;
    if (record_format_ == record_webm_video) video = VideoFormat::webm;
    if (record_format_ == record_mp4_video) video = VideoFormat::mp4;
    try {
      recorder_->start(scene, video);
    } catch (const std::exception& error) {
      told.push_back(std::string("recording failed: ") + error.what());
      recording_ = false;
    }
    recorded_step_ = -1;
  }
  if (!recording_ && recorder_->active()) told.push_back(recorder_->stop());
  if (recorder_->active() && steps != recorded_step_ && drawn) {
    try {
      recorder_->write(read_frame(), time);
    } catch (const std::exception& error) {
      told.push_back(recorder_->stop());
      told.push_back(std::string("recording stopped: ") + error.what());
      recording_ = false;
    }
    recorded_step_ = steps;
  }
}

}  // namespace wobble
