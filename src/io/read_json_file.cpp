#include "read_json_file.h"

#include <cstdint>
#include <set>
#include <vector>

#include "io/input_file_limits.h"
#include "io/json_file_text.h"
#include "sim/input_error.h"
#include "sim/input_limits.h"

namespace wobble {

namespace {

using json = nlohmann::json;

// A key or string as a message shows it: quoted, escaped as JSON escapes it, cut short.
std::string shown_key(const std::string& text) {
  const std::string shown = json(text).dump(-1, ' ', false, json::error_handler_t::replace);
  return shown.size() <= 60 ? shown : shown.substr(0, 56) + "...\"";
}

// One SAX handler for both passes over a file: it checks what nlohmann does not (keys that
// appear twice in an object, the limits of io/input_file_limits.h) and keeps the first problem
// with where it was found; with `build`, it also builds the document, as nlohmann's own DOM
// parser would. Checks come before building, so a document above a limit is never held.
class CheckedJson : public nlohmann::json_sax<json> {
 public:
  // `list_sizes` is filled by the pass that checks (the items of each list, in the order the
  // lists start) and read by the pass that builds, which reserves each list's size: a list grown
  // item by item takes twice its size at its last reallocation, and the allocator seldom gives
  // the smaller blocks it left behind back.
  CheckedJson(JsonFileText& text, bool build, std::vector<std::uint32_t>& list_sizes)
      : text_(text), build_(build), list_sizes_(list_sizes) {}

  bool null() override { return value(nullptr); }
  bool boolean(bool b) override { return value(b); }
  bool number_integer(number_integer_t n) override { return value(n); }
  bool number_unsigned(number_unsigned_t n) override { return value(n); }
  bool number_float(number_float_t x, const string_t&) override { return value(x); }
  bool string(string_t& s) override { return value(std::move(s)); }
  bool binary(binary_t&) override { return value(nullptr); }  // not in JSON text

  bool start_object(std::size_t) override { return open(true); }
  bool key(string_t& k) override {
    Frame& frame = frames_.back();
    if (!frame.keys.insert(k).second) {
      return fail("key " + shown_key(k) + " appears twice in the same object" +
                  (frames_.size() > 1 ? " (" + path() + ")" : ""));
    }
    if (++keys_ > max_json_keys) {
      return fail("more than " + with_thousands_separators(max_json_keys) +
                  " keys in all objects, above Wobble's limit for " + scene_json_file.what);
    }
    frame.last_key = k;
    if (build_) slot_ = &(*built_.back())[k];
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override {
    if (!open(false)) return false;
    frames_.back().list = lists_++;
    if (!build_) {
      list_sizes_.push_back(0);
    } else if (frames_.back().list < list_sizes_.size()) {
      built_.back()->get_ref<json::array_t&>().reserve(list_sizes_[frames_.back().list]);
    }
    return true;
  }
  bool end_array() override {
    if (!build_)
      list_sizes_[frames_.back().list] = static_cast<std::uint32_t>(frames_.back().items);
    return close();
  }

  bool parse_error(std::size_t position, const std::string&,
                   const json::exception& error) override {
    syntax_error_ = true;
    error_at_ = position;
    what_ = error.what();
    return false;
  }

  // After a pass that failed: the message, less the file's path.
  std::string problem() {
    if (text_.string_too_long()) {
      return "line " + std::to_string(text_.line()) + ": a string longer than " +
             with_thousands_separators(static_cast<long>(max_json_string_bytes)) +
             " bytes, above Wobble's limit for a key or string in " + scene_json_file.what;
    }
    if (!syntax_error_) return problem_;
    if (!text_.read_content()) return "the file is empty, expected a JSON object";
    // nlohmann counts the characters read, so the offending one is the last of them.
    const long line = text_.line_of(error_at_ == 0 ? 0 : error_at_ - 1);
    // Keep what follows "... column C: " (a syntax error) or "[json.exception.ID] " (a number
    // out of range), which says what was expected; the line is given in Wobble's own form.
    const std::size_t column = what_.find("column");
    const std::size_t colon = column == std::string::npos ? column : what_.find(": ", column);
    const std::size_t bracket = what_.find("] ");
    const std::string detail = colon != std::string::npos     ? what_.substr(colon + 2)
                               : bracket != std::string::npos ? what_.substr(bracket + 2)
                                                              : what_;
    return "line " + std::to_string(line) + ": malformed JSON: " + one_line(detail);
  }

  json& document() { return document_; }

 private:
  struct Frame {
    bool object = false;
    std::set<std::string> keys;  // an object's keys so far
    std::string last_key;        // an object's latest key
    long items = 0;              // an array's items so far
    std::size_t list = 0;        // an array's place among the lists, in the order they start
  };

  bool fail(const std::string& what) {
    problem_ = "line " + std::to_string(text_.line()) + ": " + what;
    return false;
  }

  // "colliders[0]": where the value being read sits.
  std::string path() const {
    std::string text;
    for (std::size_t i = 0; i + 1 < frames_.size(); ++i) {
      const Frame& frame = frames_[i];
      if (frame.object) {
        text += (text.empty() ? "" : ".") + frame.last_key;
      } else {
        text += "[" + std::to_string(frame.items - 1) + "]";
      }
    }
    return text;
  }

  // Counts a value that is about to be added to the innermost array or object.
  bool count_item() {
    if (frames_.empty() || frames_.back().object) return true;
    ++frames_.back().items;
    if (++items_ > max_json_list_items) {
      return fail("more than " + with_thousands_separators(max_json_list_items) +
                  " items in all lists, above Wobble's limit for " + scene_json_file.what);
    }
    return true;
  }

  // Where a new value goes: the top, the end of an array, or the latest key's slot.
  json* place(json&& v) {
    if (built_.empty()) {
      document_ = std::move(v);
      return &document_;
    }
    json& parent = *built_.back();
    if (parent.is_array()) {
      parent.push_back(std::move(v));
      return &parent.back();
    }
    *slot_ = std::move(v);
    return slot_;
  }

  bool value(json&& v) {
    if (!count_item()) return false;
    if (build_) place(std::move(v));
    return true;
  }

  bool open(bool object) {
    if (!count_item()) return false;
    if (static_cast<long>(frames_.size()) >= max_json_depth) {
      return fail("lists and objects nested more than " + std::to_string(max_json_depth) +
                  " deep, above Wobble's limit for " + scene_json_file.what);
    }
    frames_.push_back(Frame{object, {}, {}, 0, 0});
    if (build_) built_.push_back(place(object ? json::object() : json::array()));
    return true;
  }

  bool close() {
    frames_.pop_back();
    if (build_) built_.pop_back();
    return true;
  }

  JsonFileText& text_;
  const bool build_;
  std::vector<std::uint32_t>& list_sizes_;
  std::size_t lists_ = 0;
  std::vector<Frame> frames_;
  long items_ = 0, keys_ = 0;
  json document_;
  std::vector<json*> built_;  // the open arrays and objects, innermost last
  json* slot_ = nullptr;      // the value of the latest key
  std::string problem_;
  bool syntax_error_ = false;
  std::size_t error_at_ = 0;
  std::string what_;
};

}  // namespace

json read_json_file(const std::string& path) {
  InputFile file(path, scene_json_file);
  JsonFileText text(file, max_json_string_bytes);
  std::vector<std::uint32_t> list_sizes;
  // First only checked, then built: a file above a limit or with a problem is refused before
  // any of it is held. The second pass checks again, in case the file changed in between.
  for (const bool build : {false, true}) {
    if (build) text.rewind();
    CheckedJson handler(text, build, list_sizes);
    if (!json::sax_parse(text.begin(), text.end(), &handler)) {
      throw InputError(path + ": " + handler.problem());
    }
    if (build) return std::move(handler.document());
  }
  return json();  // not reached
}

void release_json(json& document) {
  if (document.is_array()) {
    for (json& item : document)
      release_json(item);
    document.get_ref<json::array_t&>().clear();
  } else if (document.is_object()) {
    for (auto& item : document.items())
      release_json(item.value());
    document.get_ref<json::object_t&>().clear();
  }
}

}  // namespace wobble
