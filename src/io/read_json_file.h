#ifndef WOBBLE_IO_READ_JSON_FILE_H
#define WOBBLE_IO_READ_JSON_FILE_H

#include <nlohmann/json.hpp>
#include <string>

namespace wobble {

// Parse a JSON file: every scene file, in either format, is read through this. The file is
// checked as InputFile checks it (a regular file of at most scene_json_file.max_bytes), a
// leading UTF-8 byte-order mark is skipped, and it is parsed twice, in blocks, without ever
// holding its text: first only checked, then, when nothing was wrong, built. Throws InputError
// on one line naming the file:
//   "PATH: no such file, expected a scene (JSON)" (and InputFile's other reasons)
//   "PATH: the file is empty, expected a JSON object"
//   "PATH: line L: malformed JSON: <what nlohmann expected>"
//   "PATH: line L: colliders[0]: key "type" appears twice in the same object"
//   "PATH: line L: ..." for a file above the limits of io/input_file_limits.h (max_json_*):
//     items in all lists, keys in all objects, nesting depth, the length of a string
// The limits are checked before any of the file is kept, so that a refusal costs little memory
// whatever the file holds.
nlohmann::json read_json_file(const std::string& path);

// Empties `document`'s lists and objects, innermost first, so that destroying it takes no
// memory of its own: nlohmann's destructor first moves every item of a list into a stack of its
// own, as much memory again as the list (16 MB for a list of a million items). Recursive, as
// deep as the document (read_json_file allows max_json_depth).
void release_json(nlohmann::json& document);

// Calls release_json on `document` when the scope ends, however it is left.
class ReleaseJsonOnExit {
 public:
  explicit ReleaseJsonOnExit(nlohmann::json& document) : document_(document) {}
  ~ReleaseJsonOnExit() { release_json(document_); }
  ReleaseJsonOnExit(const ReleaseJsonOnExit&) = delete;
  ReleaseJsonOnExit& operator=(const ReleaseJsonOnExit&) = delete;

 private:
  nlohmann::json& document_;
};

}  // namespace wobble

#endif
