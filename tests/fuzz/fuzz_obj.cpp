// libFuzzer harness: an OBJ file, read by read_obj and then, as `wobble shape.obj` and
// `wobble shape.obj --fill` would, made into a surface scene and into a filled jelly.
#include <cstddef>
#include <cstdint>

#include "fuzz_folder.h"
#include "io/load_scene.h"
#include "io/read_obj.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace wobble::fuzz;
  const std::string path = write_fuzz_file("input.obj", data, size);
  bool readable = false;
  expect_success_or_input_error([&] {
    wobble::read_obj(path);
    readable = true;
  });
  if (!readable) return 0;
  expect_success_or_input_error([&] { wobble::load_scene(path); });
  expect_success_or_input_error([&] { wobble::load_scene(path, /*fill=*/true); });
  return 0;
}
