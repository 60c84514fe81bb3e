# Compiler flags of the WOBBLE_FUZZ build, included from the top CMakeLists.txt before the
# libraries are added, so that wobble_sim and wobble_io are instrumented too.
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "WOBBLE_FUZZ needs clang (libFuzzer), but the C++ compiler is "
                      "${CMAKE_CXX_COMPILER_ID}: configure a fresh build folder with "
                      "CC=clang CXX=clang++, or run scripts/fuzz.sh")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                    -fno-omit-frame-pointer -g)
# Keep assert() and eigen_assert() on whatever the build type: an out-of-range Eigen index
# inside one allocation is a bug ASan cannot see, but Eigen's own bounds check can.
add_compile_options(-UNDEBUG)
add_link_options(-fsanitize=address,undefined)
