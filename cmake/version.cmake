# lfd_version: util/version.{hpp,cpp}, the program's version line (project version, git commit,
# build date). A library of its own, linked by the program only: the commit changes with every
# commit, and only what links this library relinks then. Included from util/CMakeLists.txt.
#   -DLFD_GIT_COMMIT=abc1234   the commit for a build outside a git checkout (a source tarball)
find_package(Git QUIET)
set(LFD_GIT_COMMIT "" CACHE STRING "git commit to report when the source is not a git checkout")

set(_lfd_version_dir ${PROJECT_BINARY_DIR}/generated/version)
set(_lfd_version_header ${_lfd_version_dir}/lfd_version_info.hpp)
# Runs at every build (a custom target is always out of date); the script rewrites the header
# only when the commit or the date changed, and Ninja then recompiles one file.
add_custom_target(lfd_version_info
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DOUTPUT=${_lfd_version_header}
    -DVERSION=${PROJECT_VERSION} -DGIT_EXECUTABLE=${GIT_EXECUTABLE} -DCOMMIT=${LFD_GIT_COMMIT}
    -P ${PROJECT_SOURCE_DIR}/cmake/version_info.cmake
  BYPRODUCTS ${_lfd_version_header}
  COMMENT "Reading the git commit for lfd --version"
  VERBATIM)

add_library(lfd_version ${PROJECT_SOURCE_DIR}/util/version.cpp ${_lfd_version_header})
add_dependencies(lfd_version lfd_version_info)
target_include_directories(lfd_version PUBLIC ${PROJECT_SOURCE_DIR} PRIVATE ${_lfd_version_dir})
