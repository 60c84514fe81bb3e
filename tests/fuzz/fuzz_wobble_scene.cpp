// libFuzzer harness: Wobble's own scene JSON, read with read_json_file and built with
// load_wobble_scene. The input is the JSON, optionally followed by a line "@@@" and a mesh
// written as both input.obj and input.mesh next to it; the private folder also holds mesh.obj
// (a closed surface), mesh.mesh, mesh.node, mesh.ele and texture.png for the scene to name.
#include <cstddef>
#include <cstdint>

#include "fuzz_folder.h"
#include "io/read_json_file.h"
#include "io/wobble_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace wobble::fuzz;
  const SceneInput input = split_scene_input(data, size);
  if (names_a_path_outside(input.json)) return -1;  // -1: not added to the corpus
  for (const char* name : {"input.obj", "input.mesh"}) {
    if (input.has_attachment) {
      write_fuzz_file(name, input.attachment);
    } else {
      remove_fuzz_file(name);
    }
  }
  const std::string path = write_fuzz_file("scene.json", input.json);
  expect_success_or_input_error(
      [&] { wobble::load_wobble_scene(path, wobble::read_json_file(path)); });
  return 0;
}
