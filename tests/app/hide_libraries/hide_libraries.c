// Preloaded (LD_PRELOAD) into wobble by the tests, to play a machine without some libraries:
// dlopen of a name listed in WOBBLE_HIDE_LIBRARIES (colon-separated file names, e.g.
// "libGL.so.1:libGL.so") fails as if the file were not installed, whatever folder it is asked
// from. Everything else is opened as usual.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdlib.h>
#include <string.h>

static int hidden(const char* file) {
  const char* list = getenv("WOBBLE_HIDE_LIBRARIES");
  if (list == NULL || file == NULL) return 0;
  const char* slash = strrchr(file, '/');
  const char* name = slash ? slash + 1 : file;
  const size_t length = strlen(name);
  for (const char* at = list; *at != '\0';) {
    const char* end = strchr(at, ':');
    const size_t entry = end ? (size_t)(end - at) : strlen(at);
    if (entry == length && strncmp(at, name, length) == 0) return 1;
    if (end == NULL) break;
    at = end + 1;
  }
  return 0;
}

void* dlopen(const char* file, int mode) {
  static void* (*real)(const char*, int) = NULL;
  if (real == NULL) real = (void* (*)(const char*, int))dlsym(RTLD_NEXT, "dlopen");
  if (hidden(file)) return NULL;
  return real(file, mode);
}
