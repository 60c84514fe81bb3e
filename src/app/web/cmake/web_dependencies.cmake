# The browser build's dependencies (scripts/build-web.sh, docs/web.md). Included by the root
# CMakeLists.txt under emcmake, before anything looks for a package, so that every library of
# src/ builds unchanged for WebAssembly:
#   - Eigen, nlohmann-json and CLI11 are Debian's header-only packages, reached through a folder
#     of links, never -I/usr/include, which would put the host's C library before emscripten's;
#   - GLFW and WebGL 2 come with emscripten (-sUSE_GLFW=3); EGL is an empty target (the headless
#     mode is not built for the browser);
#   - Dear ImGui (1.86, the desktop's version), libspng and zlib are compiled from Debian's source
#     packages, which build-web.sh unpacks into WOBBLE_WEB_SOURCES.
# The find modules and package configs in this folder only say "found": the targets are here.
set(WOBBLE_WEB_SOURCES "" CACHE PATH "Debian's imgui, libspng and zlib sources, unpacked")
foreach(source imgui libspng zlib)
  if(NOT EXISTS "${WOBBLE_WEB_SOURCES}/${source}")
    message(FATAL_ERROR "WOBBLE_WEB_SOURCES: no ${source} in '${WOBBLE_WEB_SOURCES}' "
                        "(scripts/build-web.sh unpacks it)")
  endif()
endforeach()
set(web_imgui "${WOBBLE_WEB_SOURCES}/imgui")
set(web_spng "${WOBBLE_WEB_SOURCES}/libspng")
set(web_zlib "${WOBBLE_WEB_SOURCES}/zlib")

list(PREPEND CMAKE_MODULE_PATH "${CMAKE_CURRENT_LIST_DIR}")
set(Eigen3_DIR "${CMAKE_CURRENT_LIST_DIR}" CACHE PATH "" FORCE)
set(CLI11_DIR "${CMAKE_CURRENT_LIST_DIR}" CACHE PATH "" FORCE)

set(web_include "${CMAKE_BINARY_DIR}/web_include")
file(MAKE_DIRECTORY "${web_include}")
foreach(folder nlohmann CLI)
  if(NOT EXISTS "/usr/include/${folder}")
    message(FATAL_ERROR "/usr/include/${folder} is missing (scripts/build-web.sh installs it)")
  endif()
  file(CREATE_LINK "/usr/include/${folder}" "${web_include}/${folder}" SYMBOLIC)
endforeach()

add_library(Eigen3::Eigen INTERFACE IMPORTED GLOBAL)
set_target_properties(Eigen3::Eigen PROPERTIES INTERFACE_INCLUDE_DIRECTORIES /usr/include/eigen3)
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED GLOBAL)
set_target_properties(nlohmann_json::nlohmann_json PROPERTIES
                      INTERFACE_INCLUDE_DIRECTORIES "${web_include}")
add_library(CLI11::CLI11 INTERFACE IMPORTED GLOBAL)
set_target_properties(CLI11::CLI11 PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${web_include}")
add_library(glfw INTERFACE IMPORTED GLOBAL)
set_target_properties(glfw PROPERTIES INTERFACE_LINK_OPTIONS "-sUSE_GLFW=3")
add_library(OpenGL::EGL INTERFACE IMPORTED GLOBAL)

# What emscripten 3.1.6 lacks of the desktop's C++ library and GLFW (see the header).
add_compile_options("$<$<COMPILE_LANGUAGE:CXX>:-include${CMAKE_CURRENT_LIST_DIR}/../web_compat.h>")

# WebAssembly SIMD (128-bit lanes): the solve's four-lane rows (sim/solver/substitute_lanes.h,
# a GCC vector type) and what the compiler vectorizes elsewhere run two doubles an instruction
# instead of one. Every browser of the last years (Chrome 91, Firefox 89, Safari 16.4) and node
# 16 run it. docs/web.md has the step times with and without.
add_compile_options(-msimd128)
add_link_options(-msimd128)

# C++ exceptions: the loaders throw typed errors that the viewer catches and shows.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)

# Dear ImGui with its GLFW backend (Wobble draws the panel itself: render/panel_renderer.h).
add_library(wobble_web_imgui STATIC
  ${web_imgui}/imgui.cpp ${web_imgui}/imgui_draw.cpp ${web_imgui}/imgui_tables.cpp
  ${web_imgui}/imgui_widgets.cpp ${web_imgui}/imgui_demo.cpp
  ${web_imgui}/backends/imgui_impl_glfw.cpp)
target_include_directories(wobble_web_imgui SYSTEM PUBLIC ${web_imgui})
target_compile_options(wobble_web_imgui PRIVATE -w)  # not our code

add_library(wobble_web_zlib STATIC
  ${web_zlib}/adler32.c ${web_zlib}/compress.c ${web_zlib}/crc32.c ${web_zlib}/deflate.c
  ${web_zlib}/infback.c ${web_zlib}/inffast.c ${web_zlib}/inflate.c ${web_zlib}/inftrees.c
  ${web_zlib}/trees.c ${web_zlib}/uncompr.c ${web_zlib}/zutil.c)
target_include_directories(wobble_web_zlib SYSTEM PUBLIC ${web_zlib})
target_compile_options(wobble_web_zlib PRIVATE -w)

add_library(wobble_web_spng STATIC ${web_spng}/spng/spng.c)
target_include_directories(wobble_web_spng SYSTEM PUBLIC ${web_spng}/spng)
target_link_libraries(wobble_web_spng PUBLIC wobble_web_zlib)
target_compile_options(wobble_web_spng PRIVATE -w)

# src/io and src/ui ask pkg-config for spng and imgui: here it answers with the headers above
# (the libraries are linked by the web programs themselves, src/app/web/CMakeLists.txt).
set(web_pkgconfig "${CMAKE_BINARY_DIR}/web_pkgconfig")
file(WRITE "${web_pkgconfig}/spng.pc"
     "Name: spng\nDescription: libspng for the web\nVersion: 0.7.3\n"
     "Cflags: -I${web_spng}/spng\nLibs:\n")
file(WRITE "${web_pkgconfig}/imgui.pc"
     "Name: imgui\nDescription: Dear ImGui for the web\nVersion: 1.86\n"
     "Cflags: -I${web_imgui}\nLibs:\n")
set(ENV{PKG_CONFIG_LIBDIR} "${web_pkgconfig}")
set(ENV{PKG_CONFIG_PATH} "")
# Asked again at every configure, so that a new sources folder is seen.
unset(__pkg_config_checked_SPNG CACHE)
unset(__pkg_config_checked_IMGUI CACHE)
