#include "app/outputs/image_outputs.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <ostream>

#include "io/atomic_file.h"
#include "sim/input_error.h"

namespace wobble {

namespace {

// The last path component's extension in lower case (".png"), or "".
std::string lower_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

bool ends_with_png(const std::string& path) {
  return lower_extension(path) == ".png";
}

}  // namespace

std::optional<VideoFormat> ImageOutputs::record_video_format(const std::string& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".webm") return VideoFormat::webm;
  if (extension == ".mp4") return VideoFormat::mp4;
  // Names that read as one image or video file: a folder of that name would surprise.
  static const char* const refused[] = {".gif", ".webp", ".apng", ".png",  ".jpg", ".jpeg",
                                        ".avi", ".mov",  ".mkv",  ".m4v",  ".ogv", ".ogg",
                                        ".mpg", ".mpeg", ".wmv",  ".flv",  ".3gp", ".h264",
                                        ".y4m", ".bmp",  ".tif",  ".tiff", ".svg", ".pdf"};
  struct stat info {};
  const bool folder = stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
  if (!folder &&
      std::find(std::begin(refused), std::end(refused), extension) != std::end(refused)) {
    throw InputError("--record: '" + path + "' ends in " + extension +
                     ", expected a video file ending in .webm (VP9) or .mp4 (H.264), or a " +
                     "folder for PNG frames");
  }
  return std::nullopt;
}

ImageOutputs::ImageOutputs(std::string screenshot, std::string record,
                           std::optional<long> total_frames, std::ostream& progress)
    : screenshot_(std::move(screenshot)),
      record_(std::move(record)),
      total_frames_(total_frames),
      progress_(progress) {
  if (!screenshot_.empty()) {
    if (!ends_with_png(screenshot_)) {
      throw InputError("--screenshot: '" + screenshot_ + "' must end in .png");
    }
    check_output_path("--screenshot", screenshot_);
  }
  if (record_.empty()) return;
  if (const std::optional<VideoFormat> format = record_video_format(record_)) {
    check_output_path("--record", record_);
    video_ = std::make_unique<VideoFile>(record_, *format);
  } else {
    check_output_folder("--record", record_, frame_file(record_, 1));
  }
}

ImageOutputs::~ImageOutputs() = default;  // the video, if any, completes itself

void ImageOutputs::finish() {
  if (video_) video_->finish();
}

std::string ImageOutputs::frame_file(const std::string& folder, long frame, const char* extension) {
  char name[48];
  std::snprintf(name, sizeof name, "frame_%05ld%s", frame, extension);
  return folder + (folder.back() == '/' ? "" : "/") + name;
}

long ImageOutputs::start_frame_folder(const std::string& folder, const char* extension) {
  make_output_folder(folder);
  const std::string suffix = extension;
  long removed = 0;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    const std::size_t digits = name.size() - std::min(name.size(), 6 + suffix.size());  // 5 or more
    const bool frame = digits >= 5 && name.compare(0, 6, "frame_") == 0 &&
                       name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0 &&
                       name.find_first_not_of("0123456789", 6) == 6 + digits;
    std::error_code kind_error;
    if (!frame || entry.is_directory(kind_error)) continue;
    if (unlink(entry.path().c_str()) != 0) {
      throw OutputError(entry.path().string() + ": cannot remove this frame of an earlier " +
                        "recording: " + std::strerror(errno));
    }
    ++removed;
  }
  if (error) throw OutputError(folder + ": cannot list the folder: " + error.message());
  return removed;
}

void ImageOutputs::write(long frame, bool last, const RgbaImage& image, const FrameTime& time) {
  if (video_) {
    video_->write(image, time);
  } else if (!record_.empty()) {
    if (!record_folder_made_) {
      const long removed = start_frame_folder(record_);
      if (removed > 0) {
        progress_ << "wobble: note: removed " << removed << " frames of an earlier recording from "
                  << escape_control_characters(record_) << "\n";
      }
    }
    record_folder_made_ = true;
    write_png(frame_file(record_, frame), image);
  }
  if (!record_.empty()) {
    // A line per hundred frames: enough to see a long recording move, few enough for a log.
    if (frame % 100 == 0 || (last && frame >= 100)) {
      progress_ << "wobble: recorded " << frame;
      if (total_frames_) progress_ << " of " << *total_frames_;
      progress_ << " frames into " << escape_control_characters(record_) << "\n" << std::flush;
    }
  }
  if (last && !screenshot_.empty()) write_png(screenshot_, image);
}

}  // namespace wobble
