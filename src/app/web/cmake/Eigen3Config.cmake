# The browser build: Eigen3::Eigen is defined in web_dependencies.cmake.
set(Eigen3_FOUND TRUE)
