#ifndef WOBBLE_APP_OUTPUTS_VIDEO_FILE_H
#define WOBBLE_APP_OUTPUTS_VIDEO_FILE_H

#include <memory>
#include <string>

#include "io/png_image.h"

namespace wobble {

// What --record and the window's record toggle can write as one file.
enum class VideoFormat {
  webm,  // VP9 in WebM: plays in every browser
  mp4,   // H.264 (yuv420p) in MP4, its index at the front (faststart): slides and players
};

inline const char* video_extension(VideoFormat format) {
  return format == VideoFormat::webm ? ".webm" : ".mp4";
}

// When a recorded frame shows the simulation: its simulated time and the step that advanced it.
struct FrameTime {
  double seconds = 0.0;  // simulated time of the state shown (s)
  double dt = 0.0;       // the step (s); 0: unknown, the frames are then 1/60 s apart
};

// One video file written a frame at a time with FFmpeg's libraries (libavformat, libavcodec,
// libswscale): VP9 for .webm, H.264 for .mp4, both yuv420p. Each frame is stamped with its
// simulated time, so the video plays at the simulation's own speed; the time base is the first
// frame's dt (1/dt frames a second when every step is recorded, as headless does). yuv420p
// needs even sides: an odd width or height loses its last column or bottom row. A frame whose
// size differs from the first one's (a resized window) is scaled to the first size.
//
// The file is opened at the first frame and written where it is (no temporary copy), so a run
// that ends early still leaves the frames so far: finish() completes the container, and the
// destructor does so too (quietly) when an error ends the run first. A WebM reaches the disk a
// second at a time, so even a run killed by a signal leaves one that decodes. Errors at run
// time throw OutputError naming the file.
class VideoFile {
 public:
  VideoFile(std::string path, VideoFormat format);
  ~VideoFile();
  VideoFile(const VideoFile&) = delete;
  VideoFile& operator=(const VideoFile&) = delete;

  // Encode `image` (RGBA, rows from the top) as the frame at `time`. A frame at an earlier time
  // than the last one (the simulation was reset) follows it one tick later; a frame within the
  // last one's tick is left out.
  void write(const RgbaImage& image, const FrameTime& time);
  // Flush the encoder, write the container's index and close the file. Once; later calls do
  // nothing. Throws OutputError when the file cannot be completed.
  void finish();

  const std::string& path() const { return path_; }
  long frames() const { return frames_; }

 private:
  struct Encoder;  // FFmpeg's state, kept out of this header
  std::string path_;
  VideoFormat format_;
  std::unique_ptr<Encoder> encoder_;
  long frames_ = 0;
  bool finished_ = false;
};

}  // namespace wobble

#endif
