# The browser build: CLI11::CLI11 is defined in web_dependencies.cmake.
set(CLI11_FOUND TRUE)
