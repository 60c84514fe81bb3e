#ifndef WOBBLE_APP_OUTPUTS_IMAGE_OUTPUTS_H
#define WOBBLE_APP_OUTPUTS_IMAGE_OUTPUTS_H

#include <iosfwd>
#include <optional>
#include <string>

#include "io/png_image.h"

namespace wobble {

// --screenshot FILE.png and --record DIR, the same in both modes.
class ImageOutputs {
 public:
  // Checks the paths before any work is done (InputError, see check_output_path): the
  // screenshot must end in .png and be writable; the record folder must exist or be possible
  // to make in an existing parent. Nothing is created before the first frame is written.
  // `total_frames` (if known) lets long recordings report progress on `progress`.
  ImageOutputs(std::string screenshot, std::string record_folder, std::optional<long> total_frames,
               std::ostream& progress);

  bool any() const { return !screenshot_.empty() || !record_folder_.empty(); }
  // Whether a frame (the last one, or not) needs its pixels read back.
  bool wants(bool last) const { return !record_folder_.empty() || (last && !screenshot_.empty()); }
  // Write frame `frame`: into the record folder, and as the screenshot if it is the last.
  void write(long frame, bool last, const RgbaImage& image);

  // The record folder's file for a frame: DIR/frame_00001.png (or another extension).
  static std::string frame_file(const std::string& folder, long frame,
                                const char* extension = ".png");
  // Makes `folder` if it is missing, and removes the frames of an earlier recording in it
  // (files named as frame_file names them, with `extension`), so that a recording into a
  // folder that held a longer one never leaves that one's frames after its own. Other files
  // are left alone. Returns how many frames were removed. OutputError if one cannot be.
  static long start_frame_folder(const std::string& folder, const char* extension = ".png");

 private:
  std::string screenshot_, record_folder_;
  bool record_folder_made_ = false;  // made at the first frame, once all input was accepted
  std::optional<long> total_frames_;
  std::ostream& progress_;
};

}  // namespace wobble

#endif
