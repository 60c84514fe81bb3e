#include "fuzz_folder.h"

#include <stdlib.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "sim/input_error.h"

namespace wobble::fuzz {

namespace {

// A closed, consistently oriented tetrahedron surface, so a scene can fill it with tetrahedra,
// with texture coordinates.
const char* const kSurface =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "vt 0 0\nvt 1 0\nvt 0 1\n"
    "f 1/1 3/3 2/2\nf 1/1 2/2 4/3\nf 1/1 4/3 3/3\nf 2/2 3/3 4/3\n";
const char* const kMedit =
    "MeshVersionFormatted 1\nDimension 3\n"
    "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
    "Tetrahedra\n1\n1 2 3 4 0\nEnd\n";
const char* const kNode = "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
const char* const kEle = "1 4 0\n1 1 2 3 4\n";
// The loaders check that a texture exists but do not decode it: the PNG signature will do.
const char* const kTexture = "\x89PNG\r\n\x1a\n";

void write_bytes(const std::string& path, const char* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(data, static_cast<std::streamsize>(size));
  if (!out) {
    std::fprintf(stderr, "wobble fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
}

// The private folder, with the fixtures in it; removed when the process exits.
class Folder {
 public:
  Folder() {
    const char* base = std::getenv("TMPDIR");
    std::string pattern =
        std::string(base != nullptr && *base != '\0' ? base : "/tmp") + "/wobble-fuzz-XXXXXX";
    if (mkdtemp(pattern.data()) == nullptr) {
      std::perror("wobble fuzz: mkdtemp");
      std::abort();
    }
    path_ = pattern;
    const std::pair<const char*, const char*> fixtures[] = {
        {"mesh.obj", kSurface}, {"mesh.mesh", kMedit},     {"mesh.node", kNode},
        {"mesh.ele", kEle},     {"texture.png", kTexture},
    };
    for (const auto& [file, text] : fixtures)
      write_bytes(path_ + "/" + file, text, std::strlen(text));
  }
  ~Folder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  Folder(const Folder&) = delete;
  Folder& operator=(const Folder&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace

const std::string& fuzz_folder() {
  static const Folder folder;
  return folder.path();
}

std::string write_fuzz_file(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz_folder() + "/" + name;
  write_bytes(path, reinterpret_cast<const char*>(data), size);
  return path;
}

std::string write_fuzz_file(const std::string& name, const std::string& text) {
  return write_fuzz_file(name, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

void remove_fuzz_file(const std::string& name) {
  std::error_code ignored;
  std::filesystem::remove(fuzz_folder() + "/" + name, ignored);
}

SceneInput split_scene_input(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string marker = "\n@@@\n";
  SceneInput input;
  const std::size_t at = text.find(marker);
  if (at == std::string::npos) {
    input.json = text;
    return input;
  }
  input.json = text.substr(0, at);
  input.attachment = text.substr(at + marker.size());
  input.has_attachment = true;
  return input;
}

bool names_a_path_outside(const std::string& json) {
  const nlohmann::json document = nlohmann::json::parse(json, nullptr, false);
  if (document.is_discarded()) return false;
  // An explicit stack: nesting is as deep as the fuzzer likes.
  std::vector<const nlohmann::json*> pending = {&document};
  while (!pending.empty()) {
    const nlohmann::json* value = pending.back();
    pending.pop_back();
    if (value->is_string() && value->get_ref<const std::string&>().find('/') != std::string::npos)
      return true;
    if (value->is_structured()) {
      for (const nlohmann::json& child : *value)
        pending.push_back(&child);
    }
  }
  return false;
}

void expect_success_or_input_error(const std::function<void()>& load) {
  try {
    load();
  } catch (const InputError& error) {
    const std::string message = error.what();
    const char* broken = nullptr;
    if (message.empty()) {
      broken = "is empty";
    } else if (message.find_first_of("\n\r") != std::string::npos) {
      broken = "is more than one line";
    } else if (message.find(fuzz_folder()) == std::string::npos) {
      broken = "names no input file";
    }
    if (broken != nullptr) {
      std::fprintf(stderr, "wobble fuzz: the InputError message %s: \"%s\"\n", broken,
                   message.c_str());
      std::abort();
    }
  }
}

}  // namespace wobble::fuzz
