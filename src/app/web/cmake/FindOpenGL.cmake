# The browser build: the target is defined in web_dependencies.cmake.
set(OpenGL_FOUND TRUE)
