#ifndef WOBBLE_RENDER_SHADER_PROGRAM_H
#define WOBBLE_RENDER_SHADER_PROGRAM_H

#include <glad/gl.h>

#include <string>

namespace wobble {

// A linked vertex + fragment program built from two files of shaders/ (by file name, e.g.
// "mesh.vert"). Needs a current GL context. Throws std::runtime_error naming the file and
// quoting the driver's log when a shader does not compile or the program does not link.
class ShaderProgram {
 public:
  ShaderProgram(const std::string& vertex_file, const std::string& fragment_file);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const { glUseProgram(program_); }
  // Location of a uniform; -1 (which GL ignores) when the linker removed it.
  GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }

 private:
  GLuint program_ = 0;
};

}  // namespace wobble

#endif
