// Simulation::step must not allocate: buffers live in the simulation, so a frame costs no trips
// to the allocator. Eigen allocates with malloc rather than operator new, so this test replaces
// malloc itself (glibc's __libc_malloc does the work) and counts calls while a flag is up. It
// has an executable of its own so the replacement touches no other test.
#include <gtest/gtest.h>

#include <cstdlib>

#include "sim/builtin_scenes.h"
#include "sim/simulation.h"

#if defined(__SANITIZE_ADDRESS__)
#define WOBBLE_MALLOC_REPLACED 0  // the sanitizer owns malloc
#else
#define WOBBLE_MALLOC_REPLACED 1
namespace {
long malloc_calls = 0;
bool counting = false;
}  // namespace
extern "C" void* __libc_malloc(std::size_t size);
extern "C" void* malloc(std::size_t size) {
  if (counting) ++malloc_calls;
  return __libc_malloc(size);
}
#endif

namespace {

#if WOBBLE_MALLOC_REPLACED
long count_mallocs(const std::function<void()>& work) {
  malloc_calls = 0;
  counting = true;
  work();
  counting = false;
  return malloc_calls;
}
#endif

TEST(SimulationAllocation, StepAllocatesNothing) {
#if !WOBBLE_MALLOC_REPLACED
  GTEST_SKIP() << "malloc cannot be counted under AddressSanitizer";
#else
  // The counter itself works: one malloc is one count.
  EXPECT_EQ(count_mallocs([] { std::free(std::malloc(16)); }), 1);
  for (const std::string& name : wobble::builtin_scene_names()) {
    SCOPED_TRACE(name);
    const wobble::Scene scene = wobble::make_builtin_scene(name);
    wobble::Simulation simulation(scene.network, scene.pins, scene.params, scene.initial_velocity);
    simulation.step();
    EXPECT_EQ(count_mallocs([&] { simulation.step(); }), 0);
    // Nor does moving a pin target, which the viewer does every frame while dragging.
    const int pin = scene.pins.front();
    EXPECT_EQ(count_mallocs([&] {
                simulation.set_pin_target(pin,
                                          simulation.pin_target(pin) + Eigen::Vector3d(0.01, 0, 0));
                simulation.step();
              }),
              0);
  }
#endif
}

}  // namespace
