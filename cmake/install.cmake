# Install rules and the Debian packages. Included once, at the end of the top-level
# CMakeLists.txt, after every module has defined its targets; module CMakeLists.txt files hold
# no install rules.
#
#   cmake --install build --prefix P   P/bin/lfd                      the program      (runtime)
#                                      P/share/lfd/                   its data         (runtime)
#                                      P/share/doc/lfd/               README, LICENSE  (runtime)
#                                      P/lib/liblfd_*.a               the libraries    (development)
#                                      P/include/lfd/<module>/*.hpp   their headers    (development)
#                                      P/lib/cmake/lfd/               find_package(lfd) (development)
#   cpack -G DEB (scripts/package.sh)  lfd_<version>_<arch>.deb (runtime) and
#                                      lfd-dev_<version>_<arch>.deb (development)
#
# Libraries: every library target named lfd_* that is defined outside tests/, bench/ and fuzz/
# is installed and exported as lfd::<name>, with the headers of its folder (and of subfolders
# that no other library owns) under include/lfd/<folder>/. A new module library therefore needs
# nothing here; to keep one out, add it to LFD_INSTALL_EXCLUDE. A library that links something
# new from outside the project needs a line in _lfd_dependency_table below (how lfdConfig.cmake
# finds it, which Debian package holds it); configuring warns when one is missing.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(LFD_INSTALL_EXCLUDE "" CACHE STRING "lfd_* library targets not to install (a list)")
set(LFD_PACKAGE_MAINTAINER "lfd maintainers <maintainers@lfd.invalid>" CACHE STRING
    "Maintainer field of the Debian packages")
set(LFD_UDEV_RULES_DIR "lib/udev/rules.d" CACHE STRING
    "where data/udev/*.rules are installed, relative to the install prefix")
set(_lfd_config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/lfd)
set(_lfd_include_dir ${CMAKE_INSTALL_INCLUDEDIR}/lfd)

# ---------------------------------------------------------------------------------------------
# The program and its data
if(TARGET lfd)
  install(TARGETS lfd RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
endif()
# data/ as it is (display templates, demo scene, calibrations, README), found at run time by
# util/data_dir.hpp relative to the program; udev rules go where udev reads them.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION ${CMAKE_INSTALL_DATADIR}/lfd
  COMPONENT runtime PATTERN udev EXCLUDE PATTERN systemd EXCLUDE)
file(GLOB _lfd_udev_rules CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/data/udev/*.rules)
if(_lfd_udev_rules)
  install(FILES ${_lfd_udev_rules} DESTINATION ${LFD_UDEV_RULES_DIR} COMPONENT runtime)
endif()
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE
  DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
# lfd serve's systemd user unit (docs/serve.md), with the installed program's path.
set(LFD_SYSTEMD_USER_UNIT_DIR "lib/systemd/user" CACHE STRING
    "where the lfd-serve user unit is installed, relative to the install prefix")
configure_file(${PROJECT_SOURCE_DIR}/data/systemd/lfd-serve.service.in ${PROJECT_BINARY_DIR}/lfd-serve.service @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/lfd-serve.service DESTINATION ${LFD_SYSTEMD_USER_UNIT_DIR} COMPONENT runtime)
# Debian's place for the license: /usr/share/doc/<package>/copyright; the notices of the code
# compiled into the program (Ceres is a static library on Debian; CLI11, nlohmann-json, Eigen).
install(FILES ${PROJECT_SOURCE_DIR}/cmake/debian/copyright
  ${PROJECT_SOURCE_DIR}/cmake/debian/THIRD-PARTY-NOTICES
  DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/cmake/debian/copyright
  DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/lfd-dev COMPONENT development)

# The Python package lfd (python/, docs/python.md): the extension and its Python files, where
# Debian's python3 finds packages (/usr/lib/python3/dist-packages under the .deb's /usr).
set(LFD_PYTHON_INSTALL_DIR "lib/python3/dist-packages" CACHE STRING
    "where the Python package lfd is installed, relative to the install prefix")
if(TARGET lfd_python)
  install(TARGETS lfd_python LIBRARY DESTINATION ${LFD_PYTHON_INSTALL_DIR}/lfd COMPONENT runtime)
  install(FILES ${LFD_PYTHON_FILES} DESTINATION ${LFD_PYTHON_INSTALL_DIR}/lfd COMPONENT runtime)
endif()

# ---------------------------------------------------------------------------------------------
# The libraries: found by looking (see the top of this file).
function(_lfd_collect_targets dir out)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    _lfd_collect_targets(${sub} more)
    list(APPEND targets ${more})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

_lfd_collect_targets(${PROJECT_SOURCE_DIR} _lfd_all_targets)
set(LFD_INSTALLED_LIBRARIES)
foreach(t IN LISTS _lfd_all_targets)
  get_target_property(type ${t} TYPE)
  get_target_property(dir ${t} SOURCE_DIR)
  file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${dir})
  if(NOT t MATCHES "^lfd_" OR t IN_LIST LFD_INSTALL_EXCLUDE
     OR NOT type MATCHES "^(STATIC|SHARED|OBJECT|INTERFACE)_LIBRARY$"
     OR rel MATCHES "^(tests|bench|fuzz)(/|$)")
    continue()
  endif()
  list(APPEND LFD_INSTALLED_LIBRARIES ${t})
endforeach()
message(STATUS "lfd: installing the libraries ${LFD_INSTALLED_LIBRARIES}")

# Paths into the source or build tree are for the build tree only: an installed target's
# include folder is include/lfd (install(TARGETS ... INCLUDES) below), and the compile-time
# data paths (LFD_DATA_DIR) stay out of installed consumers. Module CMakeLists.txt files write
# plain `target_include_directories(x PUBLIC ${PROJECT_SOURCE_DIR})`; this wraps them here.
foreach(t IN LISTS LFD_INSTALLED_LIBRARIES)
  foreach(prop INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES
               INTERFACE_COMPILE_DEFINITIONS)
    get_property(values TARGET ${t} PROPERTY ${prop})
    set(wrapped)
    foreach(v IN LISTS values)
      string(FIND "${v}" "${PROJECT_SOURCE_DIR}" in_source)
      string(FIND "${v}" "${PROJECT_BINARY_DIR}" in_build)
      if(NOT v MATCHES "^\\$<" AND (NOT in_source EQUAL -1 OR NOT in_build EQUAL -1))
        set(v "$<BUILD_INTERFACE:${v}>")
      endif()
      list(APPEND wrapped "${v}")
    endforeach()
    if(values)
      set_property(TARGET ${t} PROPERTY ${prop} "${wrapped}")
    endif()
  endforeach()
endforeach()

# Headers: include/lfd/<folder of the library>/, so that installed code includes them exactly as
# the sources do ("display/lens_model.hpp" with -I<prefix>/include/lfd). A library owns
# the headers of its folder and of the subfolders that hold no other library.
set(_lfd_library_dirs)
foreach(t IN LISTS LFD_INSTALLED_LIBRARIES)
  get_target_property(dir ${t} SOURCE_DIR)
  list(APPEND _lfd_library_dirs ${dir})
endforeach()
list(REMOVE_DUPLICATES _lfd_library_dirs)
foreach(dir IN LISTS _lfd_library_dirs)
  file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${dir})
  if(rel STREQUAL "")
    message(WARNING "lfd: a library defined in the top-level folder: its headers are not installed")
    continue()
  endif()
  file(GLOB_RECURSE headers CONFIGURE_DEPENDS RELATIVE ${dir} ${dir}/*.hpp ${dir}/*.h ${dir}/*.inl)
  foreach(header IN LISTS headers)
    set(owned TRUE)
    foreach(other IN LISTS _lfd_library_dirs)
      string(FIND "${dir}/${header}" "${other}/" header_in_other)
      string(FIND "${other}" "${dir}/" other_below_dir)
      if(header_in_other EQUAL 0 AND other_below_dir EQUAL 0)
        set(owned FALSE)  # it belongs to the library of the deeper folder
      endif()
    endforeach()
    if(owned)
      get_filename_component(sub ${header} DIRECTORY)
      install(FILES ${dir}/${header} DESTINATION ${_lfd_include_dir}/${rel}/${sub}
        COMPONENT development)
    endif()
  endforeach()
endforeach()

install(TARGETS ${LFD_INSTALLED_LIBRARIES} EXPORT lfdTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT development
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime
  OBJECTS DESTINATION ${CMAKE_INSTALL_LIBDIR}/lfd/objects COMPONENT development
  INCLUDES DESTINATION ${_lfd_include_dir})
install(EXPORT lfdTargets NAMESPACE lfd:: DESTINATION ${_lfd_config_dir} COMPONENT development)

# `cmake --build B --target lfd_packaged`: everything the install rules copy, nothing else
# (scripts/package.sh builds this, then runs cpack).
add_custom_target(lfd_packaged)
add_dependencies(lfd_packaged ${LFD_INSTALLED_LIBRARIES})
if(TARGET lfd)
  add_dependencies(lfd_packaged lfd)
endif()
if(TARGET lfd_python)
  add_dependencies(lfd_packaged lfd_python)
endif()

# lfd's libbridge_inproc (docs/bridge-inproc.md), in the runtime package, in a folder named with the
# Bridge version it answers to (the vendor clients' legacy list reads the version from the folder's
# name); `lfd bridge register` finds it relative to the program. The package does not register it.
if(TARGET bridge_inproc)
  install(TARGETS bridge_inproc LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/lfd/${LFD_BRIDGE_VERSION_DIR}
    COMPONENT runtime NAMELINK_SKIP)
  add_dependencies(lfd_packaged bridge_inproc)
endif()

# ---------------------------------------------------------------------------------------------
# What the exported libraries link from outside the project: how lfdConfig.cmake finds it and
# which Debian package a consumer needs for it. One entry a line:
#   <name in the link interface (regex)> | <lines for lfdConfig.cmake> | <Debian package>
# PkgConfig::<P> imported targets are handled from the module name CMake cached for them.
set(_lfd_dependency_table
  "^fmt::|find_dependency(fmt)|libfmt-dev"
  "^spdlog::|find_dependency(spdlog)|libspdlog-dev"
  "^nlohmann_json::|find_dependency(nlohmann_json)|nlohmann-json3-dev"
  "^CLI11::|find_dependency(CLI11)|libcli11-dev"
  "^OpenMP::|find_dependency(OpenMP)|"
  "^Threads::|find_dependency(Threads)|"
  "^ZLIB::|find_dependency(ZLIB)|zlib1g-dev"
  "^Eigen3::|find_dependency(Eigen3)|libeigen3-dev"
  "^Ceres::|find_dependency(Ceres)|libceres-dev"
  "^TBB::|find_dependency(TBB)|libtbb-dev"
  "^glm::|find_dependency(glm)|libglm-dev"
  "^opencv_|find_dependency(OpenCV 4 COMPONENTS @OPENCV_COMPONENTS@)|libopencv-dev, libopencv-contrib-dev"
  "^TinyGLTF::|find_dependency(TinyGLTF)|libtinygltf-dev"
  "^nng::|find_dependency(nng)|libnng-dev"
  "^Boost::|find_dependency(Boost 1.74)|libboost-dev"
)
set(_lfd_pkgconfig_packages  # pkg-config module -> Debian package
  "stb|libstb-dev" "libzstd|libzstd-dev" "glfw3|libglfw3-dev" "epoxy|libepoxy-dev" "imgui|libimgui-dev"
  "hidapi-hidraw|libhidapi-dev" "libusb-1.0|libusb-1.0-0-dev" "zlib|zlib1g-dev" "glm|libglm-dev"
  "egl|libegl-dev" "libpng16|libpng-dev"
  "libzip|libzip-dev" "libwebp|libwebp-dev")
list(APPEND _lfd_pkgconfig_packages  # media/ (lfd play)
  "libavformat|libavformat-dev" "libavcodec|libavcodec-dev" "libavutil|libavutil-dev" "libswscale|libswscale-dev")
list(APPEND _lfd_pkgconfig_packages  # serve/ (lfd serve)
  "libcbor|libcbor-dev" "cpp-httplib|libcpp-httplib-dev")

set(_lfd_links)
foreach(t IN LISTS LFD_INSTALLED_LIBRARIES)
  get_property(links TARGET ${t} PROPERTY INTERFACE_LINK_LIBRARIES)
  string(REGEX MATCHALL "[A-Za-z0-9_.+-]+(::[A-Za-z0-9_.+-]+)?" names "${links}")
  list(APPEND _lfd_links ${names})
endforeach()
list(REMOVE_DUPLICATES _lfd_links)

set(_lfd_find_code "")
set(_lfd_pkgconfig_code "")
set(_lfd_dev_packages)
set(_lfd_opencv_components)
set(_lfd_uses_pkgconfig FALSE)
foreach(name IN LISTS _lfd_links)
  if(name IN_LIST LFD_INSTALLED_LIBRARIES OR name MATCHES "^(LINK_ONLY|BUILD_INTERFACE|INSTALL_INTERFACE)$"
     OR NOT (name MATCHES "::" OR name MATCHES "^opencv_"))
    continue()  # the project's own targets, generator-expression words, plain system libraries
  endif()
  if(name MATCHES "^PkgConfig::(.+)$")
    set(prefix ${CMAKE_MATCH_1})
    set(module "${${prefix}_MODULE_NAME}")
    if(NOT module)
      string(TOLOWER ${prefix} module)
      message(WARNING "lfd: no pkg-config module cached for ${name}; lfdConfig.cmake looks for '${module}'")
    endif()
    string(APPEND _lfd_pkgconfig_code
      "if(NOT TARGET ${name})\n  pkg_check_modules(${prefix} REQUIRED QUIET IMPORTED_TARGET ${module})\nendif()\n")
    set(_lfd_uses_pkgconfig TRUE)
    set(package "")
    foreach(entry IN LISTS _lfd_pkgconfig_packages)
      if(entry MATCHES "^${module}\\|(.*)$")
        set(package ${CMAKE_MATCH_1})
      endif()
    endforeach()
    if(package)
      list(APPEND _lfd_dev_packages ${package})
    else()
      message(WARNING "lfd: no Debian package known for pkg-config module '${module}' (cmake/install.cmake)")
    endif()
    continue()
  endif()
  if(name MATCHES "^opencv_(.+)$")
    list(APPEND _lfd_opencv_components ${CMAKE_MATCH_1})
  endif()
  set(found FALSE)
  foreach(entry IN LISTS _lfd_dependency_table)
    string(REPLACE "|" ";" fields "${entry}")
    list(GET fields 0 pattern)
    if(name MATCHES "${pattern}")
      set(found TRUE)
      break()
    endif()
  endforeach()
  if(NOT found)
    message(WARNING "lfd: the installed libraries link ${name}, which cmake/install.cmake does not "
                    "know how to find: add it to _lfd_dependency_table")
  endif()
endforeach()
# One find_dependency line per table entry in use, in table order (fmt before spdlog).
foreach(entry IN LISTS _lfd_dependency_table)
  string(REPLACE "|" ";" fields "${entry}")
  list(GET fields 0 pattern)
  list(GET fields 1 code)
  list(GET fields 2 package)
  set(used FALSE)
  foreach(name IN LISTS _lfd_links)
    if(name MATCHES "${pattern}" AND NOT name IN_LIST LFD_INSTALLED_LIBRARIES)
      set(used TRUE)
    endif()
  endforeach()
  if(used)
    list(REMOVE_DUPLICATES _lfd_opencv_components)
    list(JOIN _lfd_opencv_components " " OPENCV_COMPONENTS)
    string(CONFIGURE "${code}" code @ONLY)
    string(APPEND _lfd_find_code "${code}\n")
    if(package)
      list(APPEND _lfd_dev_packages ${package})
    endif()
  endif()
endforeach()
set(LFD_CONFIG_DEPENDENCIES "${_lfd_find_code}")
if(_lfd_uses_pkgconfig)
  string(APPEND LFD_CONFIG_DEPENDENCIES "find_dependency(PkgConfig)\n${_lfd_pkgconfig_code}")
  list(APPEND _lfd_dev_packages pkg-config)
endif()
list(REMOVE_DUPLICATES _lfd_dev_packages)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/lfdConfig.cmake.in
  ${PROJECT_BINARY_DIR}/lfdConfig.cmake INSTALL_DESTINATION ${_lfd_config_dir}
  PATH_VARS CMAKE_INSTALL_DATADIR)
# 0.x: a new minor version may break the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/lfdConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/lfdConfig.cmake ${PROJECT_BINARY_DIR}/lfdConfigVersion.cmake
  DESTINATION ${_lfd_config_dir} COMPONENT development)

# ---------------------------------------------------------------------------------------------
# Debian packages (cpack -G DEB; scripts/package.sh): lfd (the program and its data; its
# Depends computed by dpkg-shlibdeps from what the program links) and lfd-dev (libraries,
# headers, CMake package; Depends: lfd and the -dev packages of what the libraries link).
set(CPACK_PACKAGE_NAME lfd)
set(CPACK_PACKAGE_VENDOR "lfd")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
# CPack puts the summary before every component's description unless it is its default; the
# descriptions below start with their own synopsis line instead.
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${CMAKE_PROJECT_NAME} built using CMake")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_DIRECTORY ${PROJECT_BINARY_DIR})
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)  # configure with -DCMAKE_INSTALL_PREFIX=/usr (package.sh)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime development)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # <name>_<version>-<release>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${LFD_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME lfd)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION science)
# GL for the live calibration window comes through libglfw3 (which depends on libgl1); EGL for
# headless GL, and libGLESv2 for OpenGL ES contexts (the display side on a Raspberry Pi:
# docs/arm.md), are loaded at run time by libepoxy, which dpkg-shlibdeps cannot see (without
# libGLESv2 the first GL call on ES aborts inside libepoxy); gnuplot draws the report figures
# when present.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "libegl1, libgles2, libgl1-mesa-dri, gnuplot-nox")
# The Python package (import lfd) runs on Debian's python3 with numpy; dpkg-shlibdeps sees
# neither (the interpreter loads the extension).
if(TARGET lfd_python)
  set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "${LFD_PYTHON_DEPENDS}")
endif()
# With udev rules in the package, udev reads them at once (no replugging, no reboot).
if(_lfd_udev_rules)
  file(WRITE ${PROJECT_BINARY_DIR}/debian/postinst
    "#!/bin/sh\n"
    "set -e\n"
    "if [ \"$1\" = configure ] && command -v udevadm >/dev/null 2>&1; then\n"
    "  udevadm control --reload-rules || true\n"
    "  udevadm trigger --action=change --subsystem-match=usb --subsystem-match=hidraw || true\n"
    "fi\n")
  file(CHMOD ${PROJECT_BINARY_DIR}/debian/postinst PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE
    GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
  set(CPACK_DEBIAN_RUNTIME_PACKAGE_CONTROL_EXTRA ${PROJECT_BINARY_DIR}/debian/postinst)
endif()
set(CPACK_DEBIAN_RUNTIME_DESCRIPTION
  "toolkit for lenticular light field displays\n"
  "Calibrates, renders for and validates lenticular light field displays (Looking Glass\n"
  "units and home-built slanted-lenticular panels): estimates a unit's lens pitch, slant,\n"
  "offset, view cone and correction field from photographs of patterns (OpenCV + Ceres),\n"
  "renders 3D Gaussian Splatting scenes to light-field quilts with G2LF and interlaces them\n"
  "by the calibration, and simulates what a camera sees of the display to measure crosstalk\n"
  "and view separation. This package holds the lfd program and its data (display\n"
  "templates, a demo scene) and the Python package lfd.")
string(REPLACE ";" "" CPACK_DEBIAN_RUNTIME_DESCRIPTION "${CPACK_DEBIAN_RUNTIME_DESCRIPTION}")

set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME lfd-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
list(JOIN _lfd_dev_packages ", " _lfd_dev_depends)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS "lfd (= ${PROJECT_VERSION}), ${_lfd_dev_depends}")
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_RECOMMENDS "cmake, g++")
set(CPACK_DEBIAN_DEVELOPMENT_DESCRIPTION
  "toolkit for lenticular light field displays - libraries and headers\n"
  "The lfd toolkit's static libraries (display model, calibration, rendering, interlacing,\n"
  "validation), their headers under /usr/include/lfd and a CMake package:\n"
  "find_package(lfd) and target_link_libraries(app lfd::lfd_display).")
string(REPLACE ";" "" CPACK_DEBIAN_DEVELOPMENT_DESCRIPTION "${CPACK_DEBIAN_DEVELOPMENT_DESCRIPTION}")

include(CPack)
