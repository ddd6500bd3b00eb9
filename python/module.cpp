// The extension module lfd._lfd; the package lfd (python/lfd/__init__.py) is its public face.
#include "python/bindings.hpp"
#include "util/version.hpp"

PYBIND11_MODULE(_lfd, m) {
  m.doc() = "lfd's C++ library: displays, scenes, light-field quilts, interlacing, the display window";
  m.attr("__version__") = lfd::version_info().version;
  lfd::python::bind_errors(m);
  lfd::python::bind_display(m);
  lfd::python::bind_scenes(m);
  lfd::python::bind_quilt(m);
  lfd::python::bind_render(m);
  lfd::python::bind_window(m);
}
