// VideoFile where FFmpeg is not built in (the page): every video refuses at its first frame.
#include "app/outputs/video_file.h"

#include "io/atomic_file.h"

namespace wobble {

struct VideoFile::Encoder {};

VideoFile::VideoFile(std::string path, VideoFormat format)
    : path_(std::move(path)), format_(format) {}

VideoFile::~VideoFile() = default;

void VideoFile::write(const RgbaImage& /*image*/, const FrameTime& /*time*/) {
  throw OutputError(path_ + ": this build of Wobble writes no " +
                    std::string(video_extension(format_)) + " video (built without FFmpeg)");
}

void VideoFile::finish() {
  finished_ = true;
}

}  // namespace wobble
