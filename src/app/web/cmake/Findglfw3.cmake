# The browser build: the target is defined in web_dependencies.cmake.
set(glfw3_FOUND TRUE)
