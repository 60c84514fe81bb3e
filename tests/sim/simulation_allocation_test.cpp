// Simulation::step must not allocate: buffers live in the simulation, so a frame costs no trips
// to the allocator. Eigen allocates with malloc rather than operator new, so this test counts
// malloc calls (operator new calls malloc too) while a flag is up. It has an executable of its
// own so the counting touches no other test.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <functional>

#include "sim/shapes/builtin_scenes.h"
#include "sim/simulation.h"

// WOBBLE_SANITIZE's build defines WOBBLE_SANITIZE_BUILD for this file, which it compiles without
// the instrumentation; GCC defines __SANITIZE_ADDRESS__ under -fsanitize=address, and Clang
// answers __has_feature instead.
#if defined(WOBBLE_SANITIZE_BUILD) || defined(__SANITIZE_ADDRESS__)  // ours, GCC
#define WOBBLE_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define WOBBLE_ADDRESS_SANITIZER 1
#endif
#endif

namespace {
// Atomic, so that the compiler cannot move the flag's stores across a malloc it knows as a
// builtin (it may assume malloc reads no variable of ours), and so that threads may count.
std::atomic<long> malloc_calls{0};
std::atomic<bool> counting{false};
}  // namespace

#if defined(WOBBLE_ADDRESS_SANITIZER)
// AddressSanitizer owns malloc: a second definition here would bypass its allocator. Its
// allocator calls a hook on every allocation instead (malloc, calloc, realloc, operator new).
// GCC ships no <sanitizer/allocator_interface.h>, so the hook's installer is declared here.
extern "C" int __sanitizer_install_malloc_and_free_hooks(
    void (*malloc_hook)(const volatile void* pointer, std::size_t size),
    void (*free_hook)(const volatile void* pointer));
namespace {
void count_malloc(const volatile void*, std::size_t) {
  if (counting) ++malloc_calls;
}
void ignore_free(const volatile void*) {}  // the installer refuses a null hook
const bool hook_installed =
    __sanitizer_install_malloc_and_free_hooks(count_malloc, ignore_free) != 0;
}  // namespace
#else
// Replace malloc itself; glibc's __libc_malloc does the work.
namespace {
const bool hook_installed = true;
}  // namespace
extern "C" void* __libc_malloc(std::size_t size);
extern "C" void* malloc(std::size_t size) {
  if (counting) ++malloc_calls;
  return __libc_malloc(size);
}
#endif

namespace {

long count_mallocs(const std::function<void()>& work) {
  malloc_calls = 0;
  counting = true;
  work();
  counting = false;
  return malloc_calls.load();
}

TEST(SimulationAllocation, StepAllocatesNothing) {
  ASSERT_TRUE(hook_installed);
  // The counter itself works: one malloc is one count. The volatile pointer keeps the compiler
  // from removing the pair.
  EXPECT_EQ(count_mallocs([] {
              void* volatile block = std::malloc(16);
              std::free(block);
            }),
            1);
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
    // Nor does recording the convergence trace (the plots and --convergence-csv), plain or
    // accelerated.
    simulation.set_convergence_recording(true);
    simulation.step();
    EXPECT_EQ(count_mallocs([&] { simulation.step(); }), 0);
    simulation.apply(wobble::with_setting(simulation.params(), "chebyshev", true));
    simulation.step();
    EXPECT_EQ(count_mallocs([&] { simulation.step(); }), 0);
    EXPECT_EQ(simulation.last_convergence().iterations(), scene.params.iterations);
    // Nor does L-BFGS, traced or not.
    simulation.apply(wobble::with_setting(simulation.params(), "solver", std::string("lbfgs")));
    simulation.step();
    EXPECT_EQ(count_mallocs([&] { simulation.step(); }), 0);
    simulation.set_convergence_recording(false);
    EXPECT_EQ(count_mallocs([&] { simulation.step(); }), 0);
  }
}

}  // namespace
