#ifndef WOBBLE_APP_VIEWER_WINDOW_RECORDER_H
#define WOBBLE_APP_VIEWER_WINDOW_RECORDER_H

#include <iosfwd>
#include <memory>
#include <string>

#include "app/outputs/image_outputs.h"
#include "io/png_image.h"

namespace wobble {

// The window's record toggle (the panel's "record", F9): each new state drawn as
// DIR/frame_00001.png, frame_00002.png, ... in a new folder DIR = wobble-SCENE-frames-NNNN in
// `folder`, through the writer --record uses, so a recording from the window reads like one
// from the command line.
class WindowRecorder {
 public:
  WindowRecorder(std::string folder, std::ostream& progress);
  bool active() const { return outputs_ != nullptr; }
  // Start a new folder for `scene`. Throws InputError when it cannot be made.
  void start(const std::string& scene);
  // The next frame. Throws OutputError when it cannot be written.
  void write(const RgbaImage& image);
  // Stop; returns what the panel's notes say ("recorded N frames in DIR/").
  std::string stop();
  // "DIR/ (N frames)" while recording, else empty.
  std::string status() const;
  const std::string& directory() const { return directory_; }
  long frames() const { return frames_; }

 private:
  std::string folder_;
  std::ostream& progress_;
  std::unique_ptr<ImageOutputs> outputs_;
  std::string directory_;
  long frames_ = 0;
};

}  // namespace wobble

#endif
