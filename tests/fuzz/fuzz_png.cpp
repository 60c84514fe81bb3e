// libFuzzer harness: a texture, checked whole by texture_problem (as a scene is loaded) and
// decoded by read_png (as it is first drawn). The two must agree: texture_problem accepts
// exactly the files read_png decodes.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz_folder.h"
#include "io/png_image.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace wobble::fuzz;
  const std::string path = write_fuzz_file("input.png", data, size);
  const std::string problem = wobble::texture_problem(path);
  bool decoded = false;
  expect_success_or_input_error([&] {
    const wobble::RgbaImage image = wobble::read_png(path);
    if (image.pixels.size() != 4 * static_cast<std::size_t>(image.width) * image.height) {
      std::fprintf(stderr, "wobble fuzz: %dx%d image with %zu bytes\n", image.width, image.height,
                   image.pixels.size());
      std::abort();
    }
    decoded = true;
  });
  if (decoded != problem.empty()) {
    std::fprintf(stderr, "wobble fuzz: read_png %s a texture that texture_problem %s: %s\n",
                 decoded ? "decoded" : "refused", decoded ? "refused" : "accepted",
                 problem.c_str());
    std::abort();
  }
  return 0;
}
