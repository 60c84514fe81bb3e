#ifndef WOBBLE_APP_OUTPUTS_IMAGE_OUTPUTS_H
#define WOBBLE_APP_OUTPUTS_IMAGE_OUTPUTS_H

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>

#include "app/outputs/video_file.h"
#include "io/png_image.h"

namespace wobble {

// --screenshot FILE.png and --record DIR or --record FILE.webm / FILE.mp4, the same in both
// modes.
class ImageOutputs {
 public:
  // Checks the paths before any work is done (InputError, see check_output_path): the
  // screenshot must end in .png and be writable; a record path ending in .webm or .mp4 is a
  // video file that must be writable (video_file.h); one with another image or video extension
  // (.gif, .webp, .avi, ...) is refused; any other is a folder of PNG frames, which must exist
  // or be possible to make in an existing parent. Nothing is created before the first frame is
  // written. `total_frames` (if known) lets long recordings report progress on `progress`.
  ImageOutputs(std::string screenshot, std::string record, std::optional<long> total_frames,
               std::ostream& progress);
  ~ImageOutputs();

  bool any() const { return !screenshot_.empty() || !record_.empty(); }
  // Whether a frame (the last one, or not) needs its pixels read back.
  bool wants(bool last) const { return !record_.empty() || (last && !screenshot_.empty()); }
  // Write frame `frame`, the state at `time`: into the record folder or video, and as the
  // screenshot if it is the last.
  void write(long frame, bool last, const RgbaImage& image, const FrameTime& time);
  // At the normal end of a run: completes the video, if --record writes one (OutputError when
  // it cannot be). A run ended by an error completes it in the destructor, as far as it can.
  void finish();

  // What --record PATH writes: a video format for .webm and .mp4 (any case), nothing (a folder
  // of PNG frames) for a path without an image or video extension, or an existing folder.
  // Throws InputError naming --record for another image or video extension (.gif, .webp,
  // .avi, .mov, ...), which would otherwise become a folder of that name.
  static std::optional<VideoFormat> record_video_format(const std::string& path);

  // The record folder's file for a frame: DIR/frame_00001.png (or another extension).
  static std::string frame_file(const std::string& folder, long frame,
                                const char* extension = ".png");
  // Makes `folder` if it is missing, and removes the frames of an earlier recording in it
  // (files named as frame_file names them, with `extension`), so that a recording into a
  // folder that held a longer one never leaves that one's frames after its own. Other files
  // are left alone. Returns how many frames were removed. OutputError if one cannot be.
  static long start_frame_folder(const std::string& folder, const char* extension = ".png");

 private:
  std::string screenshot_, record_;
  std::unique_ptr<VideoFile> video_;  // --record FILE.webm or FILE.mp4; null: a folder
  bool record_folder_made_ = false;   // made at the first frame, once all input was accepted
  std::optional<long> total_frames_;
  std::ostream& progress_;
};

}  // namespace wobble

#endif
