#include "app/viewer/window_recorder.h"

#include <utility>

#include "app/viewer/window_saves.h"

namespace wobble {

WindowRecorder::WindowRecorder(std::string folder, std::ostream& progress)
    : folder_(std::move(folder)), progress_(progress) {}

void WindowRecorder::start(const std::string& scene) {
  directory_ = unused_file_name(folder_, "wobble-" + scene + "-frames", "");
  frames_ = 0;
  // The folder is made at the first frame, as --record makes its own.
  outputs_ = std::make_unique<ImageOutputs>(std::string(), directory_, std::nullopt, progress_);
}

void WindowRecorder::write(const RgbaImage& image) {
  if (!outputs_) return;
  outputs_->write(++frames_, /*last=*/false, image);
}

std::string WindowRecorder::stop() {
  outputs_.reset();
  return "recorded " + std::to_string(frames_) + " frames in " + directory_ + "/";
}

std::string WindowRecorder::status() const {
  if (!outputs_) return std::string();
  return directory_ + "/ (" + std::to_string(frames_) + " frames)";
}

}  // namespace wobble
