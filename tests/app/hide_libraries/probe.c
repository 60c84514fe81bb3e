// hidden_library_probe NAME: dlopen(NAME), as a program that needs it would; prints "opened" or
// "refused" and exits with 0 or 1. The tests run it under hide_libraries to show the hiding works.
#include <dlfcn.h>
#include <stdio.h>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const int opened = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL) != NULL;
  puts(opened ? "opened" : "refused");
  return opened ? 0 : 1;
}
