#include "image_outputs.h"

#include <sys/stat.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ostream>

#include "io/atomic_file.h"
#include "sim/input_error.h"

namespace wobble {

namespace {

bool ends_with_png(const std::string& path) {
  if (path.size() < 4) return false;
  std::string extension = path.substr(path.size() - 4);
  for (char& c : extension)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".png";
}

}  // namespace

ImageOutputs::ImageOutputs(std::string screenshot, std::string record_folder,
                           std::optional<long> total_frames, std::ostream& progress)
    : screenshot_(std::move(screenshot)),
      record_folder_(std::move(record_folder)),
      total_frames_(total_frames),
      progress_(progress) {
  if (!screenshot_.empty()) {
    if (!ends_with_png(screenshot_)) {
      throw InputError("--screenshot: '" + screenshot_ + "' must end in .png");
    }
    check_output_path("--screenshot", screenshot_);
  }
  if (!record_folder_.empty()) {
    check_output_folder("--record", record_folder_, frame_file(record_folder_, 1));
  }
}

std::string ImageOutputs::frame_file(const std::string& folder, long frame, const char* extension) {
  char name[48];
  std::snprintf(name, sizeof name, "frame_%05ld%s", frame, extension);
  return folder + (folder.back() == '/' ? "" : "/") + name;
}

void ImageOutputs::write(long frame, bool last, const RgbaImage& image) {
  if (!record_folder_.empty()) {
    if (!record_folder_made_) make_output_folder(record_folder_);
    record_folder_made_ = true;
    write_png(frame_file(record_folder_, frame), image);
    // A line per hundred frames: enough to see a long recording move, few enough for a log.
    if (frame % 100 == 0 || (last && frame >= 100)) {
      progress_ << "wobble: recorded " << frame;
      if (total_frames_) progress_ << " of " << *total_frames_;
      progress_ << " frames into " << escape_control_characters(record_folder_) << "\n"
                << std::flush;
    }
  }
  if (last && !screenshot_.empty()) write_png(screenshot_, image);
}

}  // namespace wobble
