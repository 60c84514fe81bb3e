#include "app/viewer/window_recorder.h"

#include <exception>
#include <utility>

#include "app/viewer/window_saves.h"

namespace wobble {

WindowRecorder::WindowRecorder(std::string folder, std::ostream& progress)
    : folder_(std::move(folder)), progress_(progress) {}

void WindowRecorder::start(const std::string& scene, std::optional<VideoFormat> video) {
  video_ = video.has_value();
  directory_ = video ? unused_file_name(folder_, "wobble-" + scene, video_extension(*video))
                     : unused_file_name(folder_, "wobble-" + scene + "-frames", "");
  frames_ = 0;
  // The folder or the file is made at the first frame, as --record makes its own.
  outputs_ = std::make_unique<ImageOutputs>(std::string(), directory_, std::nullopt, progress_);
}

void WindowRecorder::write(const RgbaImage& image, const FrameTime& time) {
  if (!outputs_) return;
  outputs_->write(frames_ + 1, /*last=*/false, image, time);
  ++frames_;
}

std::string WindowRecorder::stop() {
  std::unique_ptr<ImageOutputs> outputs = std::move(outputs_);
  if (!video_) return "recorded " + std::to_string(frames_) + " frames in " + directory_ + "/";
  try {
    if (outputs) outputs->finish();
  } catch (const std::exception& error) {
    return std::string("recording failed: ") + error.what();
  }
  if (frames_ == 0) return "recorded no frame: " + directory_ + " was not written";
  return "recorded " + std::to_string(frames_) + " frames as " + directory_;
}

std::string WindowRecorder::status() const {
  if (!outputs_) return std::string();
  return directory_ + (video_ ? "" : "/") + " (" + std::to_string(frames_) + " frames)";
}

}  // namespace wobble
