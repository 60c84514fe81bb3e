#include "shader_program.h"

#include <stdexcept>
#include <string>

#include "shader_sources.h"

namespace wobble {

namespace {

const char* find_source(const std::string& file_name) {
  for (int i = 0; i < shader_source_count; ++i) {
    if (file_name == shader_sources[i].file_name) return shader_sources[i].text;
  }
  throw std::runtime_error("shaders/" + file_name + ": no such shader was built in");
}

// The driver's log for a shader or program that failed (glGetShaderInfoLog or
// glGetProgramInfoLog), on one line.
std::string failure_log(GLuint object, PFNGLGETSHADERINFOLOGPROC get_log) {
  char buffer[2048] = {};
  get_log(object, sizeof buffer - 1, nullptr, buffer);
  std::string log = buffer;
  for (char& c : log) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!log.empty() && log.back() == ' ')
    log.pop_back();
  return log;
}

GLuint compile(GLenum type, const std::string& file_name) {
  const char* text = find_source(file_name);
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = failure_log(shader, glGetShaderInfoLog);
    glDeleteShader(shader);
    throw ShaderError("shaders/" + file_name + ": does not compile: " + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& vertex_file, const std::string& fragment_file) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_file);
  GLuint fragment = 0;
  try {
    fragment = compile(GL_FRAGMENT_SHADER, fragment_file);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = failure_log(program_, glGetProgramInfoLog);
    glDeleteProgram(program_);
    throw ShaderError("shaders/" + vertex_file + " + " + fragment_file + ": do not link: " + log);
  }
}

ShaderProgram::~ShaderProgram() {
  glDeleteProgram(program_);
}

}  // namespace wobble
