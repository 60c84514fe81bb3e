// Linked into every executable of the sanitizer build (WOBBLE_SANITIZE), and nowhere else.
//
// Mesa unloads its driver (dri/swrast_dri.so, with llvmpipe) with dlclose when the EGL display
// is terminated, while its global tables still point to blocks it allocated. Once the library
// is unmapped, LeakSanitizer finds those blocks referenced from nowhere and reports them as
// leaks, and it can no longer name the library that allocated them: every frame reads
// "<unknown module>", so no suppression by library name can match them. This is the old
// LeakSanitizer limitation with dlclose (google/sanitizers issue 89).
//
// An executable's own dlclose takes precedence over the C library's for every library the
// program loads, so this one keeps every library mapped until the process exits, as if each had
// been opened with RTLD_NODELETE. The driver's blocks stay reachable from its globals, and a
// real leak in a system library still shows, with its library's name, for lsan.supp to judge.
#include <dlfcn.h>

extern "C" int dlclose(void* handle) noexcept {
  static_cast<void>(handle);
  return 0;  // success: the handle stays valid, and the library stays loaded
}
