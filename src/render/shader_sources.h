#ifndef WOBBLE_RENDER_SHADER_SOURCES_H
#define WOBBLE_RENDER_SHADER_SOURCES_H

namespace wobble {

// The GLSL files of shaders/, compiled into the program at build time (embed_shaders.cmake).
struct ShaderSource {
  const char* file_name;  // e.g. "mesh.vert"
  const char* text;
};
extern const ShaderSource shader_sources[];
extern const int shader_source_count;

}  // namespace wobble

#endif
