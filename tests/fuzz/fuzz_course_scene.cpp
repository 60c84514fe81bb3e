// libFuzzer harness: the course's scene JSON, as load_course_scene(path) reads it. The input is
// the JSON, optionally followed by a line "@@@" and an OBJ written as input.obj next to it; the
// private folder also holds mesh.obj and texture.png for "obj" and "png" to name.
#include <cstddef>
#include <cstdint>

#include "fuzz_folder.h"
#include "io/course_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace wobble::fuzz;
  const SceneInput input = split_scene_input(data, size);
  if (names_a_path_outside(input.json)) return -1;  // -1: not added to the corpus
  if (input.has_attachment) {
    write_fuzz_file("input.obj", input.attachment);
  } else {
    remove_fuzz_file("input.obj");
  }
  const std::string path = write_fuzz_file("scene.json", input.json);
  expect_success_or_input_error([&] { wobble::load_course_scene(path); });
  return 0;
}
