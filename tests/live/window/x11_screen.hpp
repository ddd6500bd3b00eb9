#pragma once
// What the X server shows: the root window of $DISPLAY read with XGetImage, as 8-bit RGB
// (row 0 = top). Under Xvfb this is the virtual screen's framebuffer, so a test sees the
// pixels a monitor would get, independent of the GL context that drew them.
#include <stdexcept>

#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include "util/image.hpp"

namespace lfd::test {

inline Image8 grab_x11_screen() {
  Display* display = XOpenDisplay(nullptr);
  if (!display) throw std::runtime_error("XOpenDisplay failed (no DISPLAY?)");
  const Window root = DefaultRootWindow(display);
  XWindowAttributes attributes;
  XGetWindowAttributes(display, root, &attributes);
  XImage* x = XGetImage(display, root, 0, 0, unsigned(attributes.width),
                        unsigned(attributes.height), AllPlanes, ZPixmap);
  if (!x) {
    XCloseDisplay(display);
    throw std::runtime_error("XGetImage of the root window failed");
  }
  Image8 image(attributes.width, attributes.height, 3);
  for (int y = 0; y < image.height; ++y)
    for (int xx = 0; xx < image.width; ++xx) {
      const unsigned long p = XGetPixel(x, xx, y);  // 24-bit TrueColor: 0xRRGGBB
      image.at(xx, y, 0) = uint8_t((p & x->red_mask) >> 16);
      image.at(xx, y, 1) = uint8_t((p & x->green_mask) >> 8);
      image.at(xx, y, 2) = uint8_t(p & x->blue_mask);
    }
  XDestroyImage(x);
  XCloseDisplay(display);
  return image;
}

}  // namespace lfd::test
