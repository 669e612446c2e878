# Eigen for the web build: from the build's own include folder (web/CMakeLists.txt).
if(NOT TARGET Eigen3::Eigen)
  add_library(Eigen3::Eigen INTERFACE IMPORTED)
  set_target_properties(Eigen3::Eigen PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${DRAGON_WEB_INCLUDE}")
endif()
set(Eigen3_FOUND TRUE)
set(Eigen3_VERSION 3.4.0)
