#include "app/viewer/viewer_files.h"

#include <exception>
#include <filesystem>
#include <utility>

#include "io/load_scene.h"

namespace wobble {

ViewerFiles::ViewerFiles(Hooks hooks, bool page)
    : hooks_(std::move(hooks)),
      page_(page),
      missing_texture_(page ? MissingTexture::note : MissingTexture::refuse) {
  if (page_) save_and_record_.hide_record();
}

bool ViewerFiles::open_file(const std::string& path, const std::string& hidden_folder) {
  // What is said of a dropped file names it without the folder the page put the dropped files
  // in: the user dropped "banner.json", not "/opened/2/a/b/c/banner.json".
  const auto as_dropped = [&hidden_folder](std::string text) {
    const std::string folder = hidden_folder + "/";
    for (std::size_t at = hidden_folder.empty() ? std::string::npos : text.find(folder);
         at != std::string::npos; at = text.find(folder, at))
      text.erase(at, folder.size());
    return text;
  };
  try {
    Scene scene = load_scene(path, false, missing_texture_);
    for (std::string& note : scene.notes)
      note = as_dropped(note);
    const std::vector<std::string> notes = scene.notes;
    hooks_.open(std::move(scene), path);
    // A file's notes (a texture that did not come with it, drawn untextured) on screen too, as
    // the command line prints them: the panel's notes are out of sight below its sections.
    for (const std::string& note : notes)
      post(note);
    return true;
  } catch (const std::exception& error) {
    // In the notes, and on screen (a dropped file's reason would otherwise go unseen).
    tell(as_dropped(error.what()));
    return false;
  }
}

bool ViewerFiles::open_files(const std::vector<std::string>& paths) {
  if (paths.empty()) return false;
  std::string chosen = paths.back();
  for (const std::string& path : paths) {
    const std::string name = std::filesystem::path(path).extension().string();
    if (name == ".json" || name == ".JSON") chosen = path;
  }
  // The page's dropped files lie in a folder of its own making; a window's have real paths.
  return open_file(chosen, page_ ? std::filesystem::path(chosen).parent_path().string() : "");
}

void ViewerFiles::tell(const std::string& what) {
  if (hooks_.note) hooks_.note(what);
  post(what);
}

void ViewerFiles::write_frame(const std::string& scene, long steps, const FrameTime& time,
                              bool drawn, const std::function<RgbaImage()>& read_frame) {
  for (const std::string& what :
       save_and_record_.write_frame(scene, steps, drawn, read_frame, time))
    tell(what);
}

}  // namespace wobble
