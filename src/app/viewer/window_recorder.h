#ifndef WOBBLE_APP_VIEWER_WINDOW_RECORDER_H
#define WOBBLE_APP_VIEWER_WINDOW_RECORDER_H

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>

#include "app/outputs/image_outputs.h"
#include "app/outputs/video_file.h"
#include "io/png_image.h"

namespace wobble {

// The window's record toggle (the panel's "record", F9), through the writer --record uses, so a
// recording from the window reads like one from the command line. Each recording is new, in
// `folder`: either each new state drawn as DIR/frame_00001.png, frame_00002.png, ... in a new
// folder DIR = wobble-SCENE-frames-NNNN, or one video wobble-SCENE-NNNN.webm (or .mp4) whose
// frames play at their simulated time.
class WindowRecorder {
 public:
  WindowRecorder(std::string folder, std::ostream& progress);
  bool active() const { return outputs_ != nullptr; }
  // Start a new folder of PNG frames for `scene`, or a new video file in `video`'s format.
  // Throws InputError when it cannot be made.
  void start(const std::string& scene, std::optional<VideoFormat> video = std::nullopt);
  // The next frame, the state at `time` (a video's clock; PNG frames are only numbered). Throws
  // OutputError when it cannot be written.
  void write(const RgbaImage& image, const FrameTime& time = FrameTime());
  // Stop, completing a video; returns what the panel's notes say ("recorded N frames in DIR/",
  // "recorded N frames as FILE.webm", or why the video could not be completed).
  std::string stop();
  // "DIR/ (N frames)" or "FILE.webm (N frames)" while recording, else empty.
  std::string status() const;
  // The folder, or the video file, of the recording in progress or the last one.
  const std::string& directory() const { return directory_; }
  long frames() const { return frames_; }

 private:
  std::string folder_;
  std::ostream& progress_;
  std::unique_ptr<ImageOutputs> outputs_;
  std::string directory_;  // the folder, or the video file
  bool video_ = false;
  long frames_ = 0;
};

}  // namespace wobble

#endif
