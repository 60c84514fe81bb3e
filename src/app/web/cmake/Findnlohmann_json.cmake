# The browser build: the target is defined in web_dependencies.cmake.
set(nlohmann_json_FOUND TRUE)
