#ifndef WOBBLE_TESTS_FUZZ_FUZZ_FOLDER_H
#define WOBBLE_TESTS_FUZZ_FUZZ_FOLDER_H

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace wobble::fuzz {

// The private folder the harnesses write their inputs into: made once per process with mkdtemp
// under $TMPDIR (default /tmp), holding small valid files a scene can refer to by name (mesh.obj, a
// closed tetrahedron surface with vt; mesh.mesh, mesh.node and mesh.ele, one tetrahedron;
// texture.png), and removed with everything in it when the process exits normally (a crashing
// process leaves it behind, which is why scripts/fuzz.sh points TMPDIR into build-fuzz/ and clears
// it).
const std::string& fuzz_folder();

// Write `size` bytes to fuzz_folder()/name, replacing any earlier file, and return its path.
std::string write_fuzz_file(const std::string& name, const std::uint8_t* data, std::size_t size);
std::string write_fuzz_file(const std::string& name, const std::string& text);

// Remove fuzz_folder()/name if it is there.
void remove_fuzz_file(const std::string& name);

// A scene input is the JSON text, optionally followed by a line "@@@" and the text of a second
// file (an attachment) that the scene may refer to. Splits `data` there; `attachment` is empty
// and `has_attachment` false when there is no such line.
struct SceneInput {
  std::string json;
  std::string attachment;
  bool has_attachment = false;
};
SceneInput split_scene_input(const std::uint8_t* data, std::size_t size);

// Whether the JSON text holds a string with a '/' in it, anywhere (or cannot be parsed, in
// which case false). Scene inputs that do are skipped: a path out of the private folder would
// make the loaders read whatever files this machine has, so that a finding would depend on it.
bool names_a_path_outside(const std::string& json);

// Run `load`, which may only succeed or throw wobble::InputError. An InputError must keep the
// loaders' promise: one non-empty line that names a file in the private folder. Anything else
// (a broken promise, another exception type) aborts, so that libFuzzer records the input.
void expect_success_or_input_error(const std::function<void()>& load);

}  // namespace wobble::fuzz

#endif
