#ifndef WOBBLE_RENDER_SHADER_PROGRAM_H
#define WOBBLE_RENDER_SHADER_PROGRAM_H

#include <glad/gl.h>

#include <stdexcept>
#include <string>

namespace wobble {

// A shader the driver does not compile, or a program it does not link: one line naming the file
// and quoting the driver's log. The command line exits with code 2, as for a missing context.
class ShaderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A linked vertex + fragment program built from two files of shaders/ (by file name, e.g.
// "mesh.vert"). Needs a current GL context. Throws ShaderError naming the file and
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
