// libFuzzer harness: a MEDIT .mesh file, read by read_medit_mesh and then, as
// `wobble shape.mesh` would, made into a volume scene.
#include <cstddef>
#include <cstdint>

#include "fuzz_folder.h"
#include "io/load_scene.h"
#include "io/read_medit_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace wobble::fuzz;
  const std::string path = write_fuzz_file("input.mesh", data, size);
  bool readable = false;
  expect_success_or_input_error([&] {
    wobble::read_medit_mesh(path);
    readable = true;
  });
  if (readable) expect_success_or_input_error([&] { wobble::load_scene(path); });
  return 0;
}
