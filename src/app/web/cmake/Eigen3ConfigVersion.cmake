# Debian 12's Eigen (web_dependencies.cmake).
set(PACKAGE_VERSION 3.4.0)
set(PACKAGE_VERSION_COMPATIBLE TRUE)
