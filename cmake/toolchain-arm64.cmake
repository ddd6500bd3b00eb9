# Cross-compiling lfd for arm64 (aarch64) on a Debian 12 amd64 machine with Debian's multiarch
# packages (scripts/cross-build-arm64.sh, docs/arm.md): crossbuild-essential-arm64's compilers,
# the :arm64 development packages in /usr/lib/aarch64-linux-gnu, and qemu-user-static to run
# what is built (the test discovery, the tests).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
# Multiarch: the arm64 libraries and headers live beside the host's under /usr.
set(CMAKE_FIND_ROOT_PATH /usr/aarch64-linux-gnu /usr)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
# pkg-config reads the arm64 .pc files only.
set(ENV{PKG_CONFIG_LIBDIR} /usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig)
set(ENV{PKG_CONFIG_PATH} "")
# What is built runs under qemu-user (test discovery, tests). -L /: the program's loader is
# /lib/ld-linux-aarch64.so.1 of libc6:arm64, the same build as the libc.so.6 every :arm64
# library is found beside. Not the cross toolchain's /usr/aarch64-linux-gnu: its loader is
# libc6-arm64-cross's point release (2.36-8cross1), and a loader and libc of different releases
# disagree on glibc's private structures: the first pthread_create then walks a stack-cache list
# that never ends, at 100 % of a core (docs/arm.md "Under qemu-user").
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64-static;-L;/)
# The .deb's architecture and its Depends (dpkg-shlibdeps reads the arm64 libraries' symbols).
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE arm64)
# Debian's multiarch library folder, as the host's .deb has (GNUInstallDirs picks it only when not
# cross-compiling): /usr/lib/aarch64-linux-gnu/lfd/lfd-bridge-*/libbridge_inproc.so. FORCE: a
# build folder configured before keeps GNUInstallDirs' "lib" in its cache otherwise.
set(CMAKE_INSTALL_LIBDIR lib/aarch64-linux-gnu CACHE PATH "object code libraries (Debian multiarch)" FORCE)
